// per-eye-view near miss: uniforms subtracted from something that is not a view vector. A volume
// lookup at `position - origin` reaches a texture coordinate but never becomes a direction; a UV
// scroll subtracts a vec2. Neither is touched: the shader is copied byte for byte.
// RUN: %stereoshift --validate-each %s -o %t.out.frag --report %t.json
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Volume { vec3 origin; vec2 scroll; } volume;
layout(set = 0, binding = 1) uniform sampler3D density;
layout(set = 0, binding = 2) uniform sampler2D detail;
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {
  float d = texture(density, (inWorldPos - volume.origin) * 0.25).r;
  outColor = vec4(d) * texture(detail, inUV - volume.scroll);
}
// CHECK: "per-eye-view": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "name_hint": "neutral",
// CHECK-NEXT: "reason": "a position-dependent lookup (volume, projector), not a view vector",
// CHECK-NEXT: "uniform": "volume.origin",
// CHECK-NEXT: "use": "texture coordinate computed from the difference without making it a direction"
// CHECK: "result": "unchanged"
