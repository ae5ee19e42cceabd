// per-eye-view: a reflection lookup (a cube map sampled along reflect(-v, n)) reads a texture *at* a
// direction computed from the view vector; no texture coordinate is moved along it. Not relief
// mapping: mono by default, no new application parameters (--per-eye-specular makes it per eye).
// RUN: %stereoshift --validate-each --verify %s -o %t.out.frag --report %t.json
// RUN: %rmchecks %t.out.frag | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Scene { vec3 cameraPos; } scene;
layout(set = 0, binding = 1) uniform samplerCube environment;
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 v = scene.cameraPos - inWorldPos;
// CHECK: vec3 v = scene.cameraPos - inWorldPos;
// CHECK-NOT: eyeOffset
  outColor = texture(environment, reflect(-v, normalize(inNormal)));
}
// REPORT: "per-eye-view": {
// REPORT-NEXT: "left_alone": [
// REPORT: "reason": "a lookup, not relief mapping: reflections and specular terms stay mono by default
// REPORT-NEXT: "uniform": "scene.cameraPos",
// REPORT: "result": "unchanged"
