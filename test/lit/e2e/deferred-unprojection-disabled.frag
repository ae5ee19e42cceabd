// --no-deferred-unprojection: a recognisable unprojection is left as it is (copied byte for byte,
// no eye parameters declared).
// RUN: %stereoshift --no-deferred-unprojection --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
// Without the flag the same shader is fixed (so the flag is what leaves it alone).
// RUN: %stereoshift --validate-each %s --report - -o %t.fixed.frag | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; } frame;
layout(set = 0, binding = 1) uniform sampler2D gDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {
  vec4 q = frame.invViewProj * vec4(inUV * 2.0 - 1.0, texture(gDepth, inUV).r, 1.0);
  outColor = vec4(q.xyz / q.w, 1.0);
}
// CHECK: "output": "copied",
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// DEFAULT: "output": "emitted",
// DEFAULT: "deferred-unprojection": {
// DEFAULT-NEXT: "fixed": [
