// per-eye-view near miss: relief self-shadowing marches the height map toward the light, so a
// direction from the light position offsets texture coordinates exactly like a view vector. The
// name says light, and that vetoes: the shader is copied byte for byte and the report says why.
// RUN: %stereoshift --validate-each %s -o %t.out.frag --report %t.json
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Sun { vec3 lightPosition; } sun;
layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inWorldPos;
layout(location = 2) in mat3 inWorldToTangent;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 l = normalize(inWorldToTangent * (sun.lightPosition - inWorldPos));
  vec2 uv = inUV;
  float shadow = 1.0;
  for (int i = 1; i <= 8; ++i) {
    uv += l.xy / max(l.z, 0.05) * 0.005;
    if (texture(heightMap, uv).r > texture(heightMap, inUV).r + 0.1 * float(i)) shadow = 0.3;
  }
  outColor = vec4(vec3(shadow), 1.0);
}
// CHECK: "per-eye-view": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "name_hint": "light-like",
// CHECK-NEXT: "reason": "the name says light (a relief self-shadowing ray marches toward the light): not a view vector; --camera-uniform forces it",
// CHECK-NEXT: "uniform": "sun.lightPosition",
// CHECK-NEXT: "use": "direction that offsets texture coordinates"
// CHECK: "result": "unchanged"
