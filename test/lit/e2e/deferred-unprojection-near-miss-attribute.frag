// Near miss: a uniform inverse matrix times an interpolated vertex attribute (a whole vec4 input)
// is not an unprojection of a sampled depth: left alone, the shader is copied byte for byte, and
// the report says why.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; } frame;
layout(location = 0) in vec4 vClipPosition;
layout(location = 0) out vec4 outColor;
void main() {
  vec4 q = frame.invViewProj * vClipPosition;
  outColor = vec4(q.xyz / q.w, 1.0);
}
// CHECK: "output": "copied",
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "matrix * vector",
// CHECK-NEXT: "matrix": "frame.invViewProj",
// CHECK-NEXT: "reason": "w is not the constant 1: not a point in NDC"
// CHECK-NEXT: }
// CHECK-NEXT: ],
// CHECK-NEXT: "result": "unchanged"
