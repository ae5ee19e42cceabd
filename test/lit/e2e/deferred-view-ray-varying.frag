// deferred-unprojection, view-ray form (SSAO style): the view ray is interpolated from the
// full-screen pass's vertex stage (frustum corners) and scaled by the linear depth read back,
// `viewPos = vViewRay * linearDepth`. Each eye's G-buffer was drawn shifted, so the pixel's view x
// gets x - eyeSign*separation*(|z| - convergence) / P00, with P00 = projection[0][0] taken from the
// matrix that re-projects the sample; that re-projection gets the clip shift back to this eye's
// screen (docs/stereo-math.md section 4, view rays).
// Spliced into its own text (the default route), the local's right-hand side through the helper:
// RUN: %stereoshift --validate-each --verify %s --report %t.json -o - | %rmchecks | FileCheck %s --check-prefix=SPLICE
// Re-emitted from the IR (an explicit --target-version takes SPIRV-Cross's route): the same fix.
// RUN: %stereoshift --validate-each --verify %s --report %t.json --target-version 450 -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform SsaoParams { mat4 projection; vec4 kernel[8]; float radius; } params;
layout(set = 0, binding = 1) uniform sampler2D linearDepthTex;
layout(location = 0) in vec2 vTexCoord;
layout(location = 1) in vec3 vViewRay;
layout(location = 0) out float outOcclusion;
void main() {
  float linearDepth = texture(linearDepthTex, vTexCoord).r;
  vec3 viewPos = vViewRay * linearDepth;
  float occlusion = 0.0;
  for (int i = 0; i < 8; ++i) {
    vec3 samplePos = viewPos + params.kernel[i].xyz * params.radius;
    vec4 offset = params.projection * vec4(samplePos, 1.0);
    vec2 sampleUV = offset.xy / offset.w * 0.5 + 0.5;
    float sampleDepth = texture(linearDepthTex, sampleUV).r;
    occlusion += sampleDepth < -samplePos.z ? 1.0 : 0.0;
  }
  outOcclusion = 1.0 - occlusion / 8.0;
}
// SPLICE: vec3 viewPos = stereoshift_view_ray_viewPos(vViewRay * linearDepth);
// SPLICE: vec4 offset = stereoshift_reproject_params_projection(params.projection * vec4(samplePos, 1.0));
// SPLICE: return stereo.eyeSign != 0.0 ? vec4(stereoshift_q.x + (stereo.eyeSign * stereo.separation) * (stereoshift_q.w - stereo.convergence), stereoshift_q.yzw) : stereoshift_q;
// SPLICE: stereoshift_p.x = stereoshift_p.x - ((stereo.eyeSign * stereo.separation) * (abs(stereoshift_p.z) - stereo.convergence)) * (1.0 / params.projection[0][0]);
// CHECK: vec3 [[P:_[0-9]+]] = vViewRay * linearDepth;
// CHECK-NEXT: float [[Z:_[0-9]+]] = [[P]].z;
// CHECK-NEXT: vec3 [[X:_[0-9]+]] = [[P]];
// CHECK-NEXT: [[X]].x = [[P]].x - (((stereo.eyeSign * stereo.separation) * ((([[Z]] < 0.0) ? (-[[Z]]) : [[Z]]) - stereo.convergence)) * (1.0 / params.projection[0].x));
// CHECK-NEXT: vec3 viewPos = mix([[P]], [[X]], bvec3(stereo.eyeSign != 0.0));
// CHECK: vec4 [[C:_[0-9]+]] = params.projection * vec4(samplePos, 1.0);
// CHECK-NEXT: precise float [[D:_[0-9]+]] = [[C]].w - stereo.convergence;
// CHECK: vec4 offset = mix([[C]], {{_[0-9]+}}, bvec4(stereo.eyeSign != 0.0));

// REPORT: "construct": "matrix * view-ray position",
// REPORT-NEXT: "fix": "x + eyeSign*separation*(w - convergence): back to this eye's screen",
// REPORT-NEXT: "matrix": "params.projection"
// REPORT: "construct": "view ray * depth",
// REPORT-NEXT: "depth": "linearDepthTex",
// REPORT: "form": "view ray interpolated from the vertex stage (vViewRay)",
// REPORT-NEXT: "projection_scale": "params.projection[0][0]"
