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
// CHECK: uniform float eyeSign;
// CHECK-NEXT: uniform float separation;
// CHECK-NEXT: uniform float convergence;
// CHECK: vec4 [[Q:_[0-9]+]] = uInvViewProj * vec4((vUV * 2.0) - vec2(1.0), (depth * 2.0) - 1.0, 1.0);
// CHECK-NEXT: vec4 [[FIXED:_[0-9]+]] = [[Q]] - (uInvViewProj[0] * ((eyeSign * separation) * (1.0 - (convergence * [[Q]].w))));
// CHECK-NEXT: bvec4 [[STEREO:_[0-9]+]] = bvec4(eyeSign != 0.0);
// CHECK-NEXT: vec4 q = vec4([[STEREO]].x ? [[FIXED]].x : [[Q]].x,
// CHECK-NEXT: vec3 worldPos = q.xyz / vec3(q.w);

// REPORT: "depth": "uDepth",
// REPORT-NEXT: "depth_range": "remapped in the shader (e.g. depth * 2 - 1)",
// REPORT: "matrix": "uInvViewProj",
// REPORT-NEXT: "ndc": "vUV"
// REPORT: "result": "changed"
