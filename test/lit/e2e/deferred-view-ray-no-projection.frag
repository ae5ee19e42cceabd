// deferred-unprojection, view-ray form in a GLSL 330 shader with loose uniforms and no projection
// matrix: the ray is built from the full-screen UV and the field of view,
// `vec3((uv*2-1) * tanHalfFov * vec2(aspect, 1), -1)`. P00 is nowhere in the shader, so the fix
// reads the injected eye parameter projScaleX, and the report names it for the application to set.
// Spliced into its own text (the default route), the local's right-hand side through the helper:
// RUN: %stereoshift --validate-each %s --report %t.json -o - | %rmchecks | FileCheck %s --check-prefix=SPLICE
// Re-emitted from the IR (an explicit --target-version takes SPIRV-Cross's route): the same fix.
// RUN: %stereoshift --validate-each %s --report %t.json --target-version 330 -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 330 core
uniform sampler2D depthMap;
uniform float tanHalfFov;
uniform float aspect;
in vec2 TexCoords;
out vec4 FragColor;
void main() {
  vec3 ray = vec3((TexCoords * 2.0 - 1.0) * tanHalfFov * vec2(aspect, 1.0), -1.0);
  vec3 position = ray * texture(depthMap, TexCoords).r;
  FragColor = vec4(position, 1.0);
}
// SPLICE: vec3 position = stereoshift_view_ray_position(ray * texture(depthMap, TexCoords).r);
// SPLICE: uniform float projScaleX;
// SPLICE: stereoshift_p.x = stereoshift_p.x - ((eyeSign * separation) * (abs(stereoshift_p.z) - convergence)) * (1.0 / projScaleX);
// CHECK: uniform float projScaleX;
// CHECK: vec3 [[P:_[0-9]+]] = ray * texture(depthMap, TexCoords).x;
// CHECK: [[X:_[0-9]+]].x = [[P]].x - {{.*}} * (1.0 / projScaleX));

// REPORT: "application_fills": "projScaleX = P[0][0], the x scale of the projection the G-buffer was drawn with
// REPORT: "construct": "view ray * depth",
// REPORT-NEXT: "depth": "depthMap",
// REPORT: "form": "view ray computed from TexCoords",
// REPORT-NEXT: "projection_scale": "projScaleX (injected: set by the application)"
