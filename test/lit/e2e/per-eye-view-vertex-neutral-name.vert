// per-eye-view near miss: the same tangent-space vector as a relief view vector, but from a uniform
// whose name does not say camera, in a vertex shader alone. Without the fragment stage nothing
// shows what it is for, so it is left alone (and reported, with what would decide it).
// RUN: %stereoshift --validate-each --verify %s -o %t.out.vert --report %t.json
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 330
layout(location = 0) in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec3 uReference;
out vec3 vDirTS;
void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vec3 n = normalize(mat3(uModel) * aNormal);
  vec3 t = normalize(mat3(uModel) * aTangent.xyz);
  mat3 toTangent = transpose(mat3(t, cross(n, t) * aTangent.w, n));
  vDirTS = toTangent * (uReference - world.xyz);
// CHECK: vDirTS = {{.*}} * (uReference - world.xyz);
  gl_Position = uViewProj * world;
}
// REPORT: "per-eye-view": {
// REPORT-NEXT: "left_alone": [
// REPORT-NEXT: {
// REPORT-NEXT: "name_hint": "neutral",
// REPORT-NEXT: "reason": "the next stage is not known to offset texture coordinates with it and the name does not say camera: convert the pipeline together (--pipeline) or force with --camera-uniform",
// REPORT-NEXT: "uniform": "uReference",
// REPORT-NEXT: "use": "vector written to vDirTS"
// REPORT: "result": "unchanged"
