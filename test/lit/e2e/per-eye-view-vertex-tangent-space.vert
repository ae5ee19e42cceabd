// per-eye-view, one vertex shader alone (no fragment stage to ask): a tangent-space vector built from
// a uniform named like a camera is taken as a relief view vector. The eye centre is derived from
// the matrix that takes the same world point to gl_Position (inverted in the shader). The light
// vector beside it, built the same way, stays mono: its name says light.
// The source splice carries the per-eye-view change: the camera's read goes through a helper that
// adds this eye's offset, the rest of the text as written (no re-emit, no note).
// RUN: %stereoshift --validate-each --verify %s -o %t.out.vert --report %t.json 2>%t.notes
// RUN: FileCheck %s --check-prefix=NOTE --allow-empty --input-file %t.notes
// NOTE-NOT: re-emitted
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 330
layout(location = 0) in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec3 uEyePos;
uniform vec3 uLightPos;
out vec3 vViewTS;
out vec3 vLightTS;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vec3 n = normalize(mat3(uModel) * aNormal);
  vec3 t = normalize(mat3(uModel) * aTangent.xyz);
  mat3 toTangent = transpose(mat3(t, cross(n, t) * aTangent.w, n));
  vViewTS = toTangent * (uEyePos - world.xyz);
  vLightTS = toTangent * (uLightPos - world.xyz);
// CHECK: vViewTS = toTangent * (stereoshift_eye_uEyePos(uEyePos) - world.xyz);
// CHECK-NEXT: vLightTS = toTangent * (uLightPos - world.xyz);
// CHECK: vec3 stereoshift_eye_uEyePos(vec3 stereoshift_camera)
// CHECK-NEXT: {
// CHECK-NEXT: return stereoshift_camera + (inverse(uViewProj) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz;
  gl_Position = uViewProj * world;
}
// REPORT: "per-eye-view": {
// REPORT-NEXT: "fixed": [
// REPORT-NEXT: {
// REPORT-NEXT: "eye_centre": "uEyePos + (inverse(uViewProj) * vec4(eyeSign*separation*convergence, 0, 0, 0)).xyz  [matrices that take the same world point to the clip position]",
// REPORT-NEXT: "loads_replaced": 1,
// REPORT-NEXT: "uniform": "uEyePos",
// REPORT-NEXT: "why": "structure + name hint: a tangent-space vector from it is written to vViewTS (single-shader mode: the next stage is not known) and the name says camera"
// REPORT: "left_alone": [
// REPORT-NEXT: {
// REPORT-NEXT: "name_hint": "light-like",
// REPORT-NEXT: "reason": "the name says light (a relief self-shadowing ray marches toward the light): not a view vector; --camera-uniform forces it",
// REPORT-NEXT: "uniform": "uLightPos",
// REPORT-NEXT: "use": "tangent-space vector output"
// REPORT: "per_eye_outputs": [
// REPORT-NEXT: "vViewTS"
// REPORT-NEXT: ],
