// per-eye-view near miss: a light position minus the world position, feeding lighting only, is not
// a view vector. The fragment shader is copied byte for byte; the report names what it saw.
// RUN: %stereoshift --validate-each %s -o %t.out.frag --report %t.json
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Lights { vec3 lightPos; vec3 lightColor; } lights;
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 l = normalize(lights.lightPos - inWorldPos);
  outColor = vec4(lights.lightColor * max(dot(normalize(inNormal), l), 0.0), 1.0);
}
// CHECK: "per-eye-view": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "name_hint": "light-like",
// CHECK-NEXT: "reason": "the name says light: not view-dependent",
// CHECK-NEXT: "uniform": "lights.lightPos",
// CHECK-NEXT: "use": "light vector"
// CHECK: "result": "unchanged"
