// Near miss: vec4(ndc, depth, 0) is a direction (w = 0), not a point: the unprojection formula
// does not apply (q.w is not 1/w), so it is left alone and reported.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; } frame;
layout(set = 0, binding = 1) uniform sampler2D gDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {
  float depth = texture(gDepth, inUV).r;
  vec4 ray = frame.invViewProj * vec4(inUV * 2.0 - 1.0, depth, 0.0);
  outColor = vec4(normalize(ray.xyz), 1.0);
}
// CHECK: "output": "copied",
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "matrix * vector",
// CHECK-NEXT: "matrix": "frame.invViewProj",
// CHECK-NEXT: "reason": "w is a constant other than 1: a direction, not a point"
// CHECK: "result": "unchanged"
