// deferred-unprojection, view-ray form with the ray made in the fragment shader: the far-plane
// point of the pixel through the inverse projection, `invProj * vec4(ndc, 1, 1)`, divided to a
// ray and scaled by depth / ray.z (`ray * d / ray.z`). The fix goes after the last scaling (the
// division by ray.z belongs to the rebuilt position) and takes 1/P00 = invProj[0][0] from the
// matrix that makes the ray; the product that makes the ray is reported as part of the fix.
// Spliced into its own text (the default route), the local's right-hand side through the helper:
// RUN: %stereoshift --validate-each --verify %s --report %t.json -o - | %rmchecks | FileCheck %s --check-prefix=SPLICE
// Re-emitted from the IR (an explicit --target-version takes SPIRV-Cross's route): the same fix.
// RUN: %stereoshift --validate-each --verify %s --report %t.json --target-version 450 -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invProj; vec2 invResolution; vec4 lightViewPos; } frame;
layout(set = 0, binding = 1) uniform sampler2D gLinearDepth;
layout(location = 0) out vec4 fragColor;
void main() {
  vec2 uv = gl_FragCoord.xy * frame.invResolution;
  vec4 farPoint = frame.invProj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
  vec3 ray = farPoint.xyz / farPoint.w;
  float d = texture(gLinearDepth, uv).r;
  vec3 viewPos = ray * d / ray.z;
  float attenuation = 1.0 / (1.0 + dot(frame.lightViewPos.xyz - viewPos, frame.lightViewPos.xyz - viewPos));
  fragColor = vec4(vec3(attenuation), 1.0);
}
// SPLICE: vec3 viewPos = stereoshift_view_ray_viewPos(ray * d / ray.z);
// SPLICE: stereoshift_p.x = stereoshift_p.x - ((stereo.eyeSign * stereo.separation) * (abs(stereoshift_p.z) - stereo.convergence)) * frame.invProj[0][0];
// CHECK: vec3 [[P:_[0-9]+]] = (ray * d) / vec3(ray.z);
// CHECK-NEXT: float [[Z:_[0-9]+]] = [[P]].z;
// CHECK-NEXT: vec3 [[X:_[0-9]+]] = [[P]];
// CHECK-NEXT: [[X]].x = [[P]].x - (((stereo.eyeSign * stereo.separation) * ((([[Z]] < 0.0) ? (-[[Z]]) : [[Z]]) - stereo.convergence)) * frame.invProj[0].x);
// CHECK-NEXT: vec3 viewPos = mix([[P]], [[X]], bvec3(stereo.eyeSign != 0.0));

// REPORT: "construct": "view ray * depth",
// REPORT-NEXT: "depth": "gLinearDepth",
// REPORT: "form": "view ray computed from gl_FragCoord and an inverse projection",
// REPORT-NEXT: "projection_scale": "1 / frame.invProj[0][0]"
// REPORT: "construct": "matrix * vector",
// REPORT-NEXT: "matrix": "frame.invProj",
// REPORT-NEXT: "reason": "makes a view ray: corrected where the ray meets the depth"
