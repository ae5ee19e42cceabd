// --no-per-eye-view: a relief fragment shader that per-eye-view would fix (its view vector offsets
// texture coordinates) is left mono and copied byte for byte. Without the option it is changed.
// RUN: %stereoshift --no-per-eye-view %s -o %t.out.frag --report %t.json
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
// RUN: %stereoshift %s -o %t.fixed.frag --report %t.fixed.json
// RUN: %not cmp %s %t.fixed.frag
// RUN: FileCheck %s --check-prefix=FIXED --input-file %t.fixed.json
#version 450
layout(set = 0, binding = 0) uniform Camera { vec3 cameraPosition; } camera;
layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inWorldPos;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 v = normalize(camera.cameraPosition - inWorldPos);
  outColor = texture(heightMap, inUV - v.xz * 0.02);
}
// CHECK: "per-eye-view": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// FIXED: "per-eye-view": {
// FIXED: "result": "changed"
