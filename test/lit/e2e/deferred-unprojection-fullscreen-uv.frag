// deferred-unprojection with an OpenGL full-screen pass: ndc from the interpolated UV (uv * 2 - 1),
// the [0,1] depth sample remapped to GL's [-1,1] in the shader (depth * 2 - 1), loose uniforms.
// The eye parameters come as loose uniforms too, and the rebuilt q is corrected before the divide.
// RUN: %stereoshift --validate-each --verify %s --report %t.json -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 330
in vec2 vUV;
uniform sampler2D uDepth;
uniform mat4 uInvViewProj;
uniform vec3 uLightPos;
out vec4 fragColor;
void main() {
  float depth = texture(uDepth, vUV).r;
  vec4 q = uInvViewProj * vec4(vUV * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec3 worldPos = q.xyz / q.w;
  fragColor = vec4(vec3(1.0 / (1.0 + length(uLightPos - worldPos))), 1.0);
}
// CHECK: vec4 q = stereoshift_unproject_uInvViewProj(uInvViewProj * vec4(vUV * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0));
// CHECK-NEXT: vec3 worldPos = q.xyz / q.w;
// CHECK: uniform float eyeSign;
// CHECK-NEXT: uniform float separation;
// CHECK-NEXT: uniform float convergence;
// CHECK-NEXT: vec4 stereoshift_unproject_uInvViewProj(vec4 stereoshift_q)
// CHECK-NEXT: {
// CHECK-NEXT: return eyeSign != 0.0 ? stereoshift_q - uInvViewProj[0] * ((eyeSign * separation) * (1.0 - convergence * stereoshift_q.w)) : stereoshift_q;

// REPORT: "depth": "uDepth",
// REPORT-NEXT: "depth_range": "remapped in the shader (e.g. depth * 2 - 1)",
// REPORT: "matrix": "uInvViewProj",
// REPORT-NEXT: "ndc": "vUV"
// REPORT: "result": "changed"
