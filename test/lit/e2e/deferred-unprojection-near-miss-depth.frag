// Near miss: z is not a texel (here the fragment's own depth, gl_FragCoord.z, and a uniform far
// plane): no G-buffer depth is unprojected, so both products are left alone and reported.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; float farDepth; } frame;
layout(location = 0) out vec4 outColor;
void main() {
  vec2 ndc = gl_FragCoord.xy / 256.0 * 2.0 - 1.0;
  vec4 self = frame.invViewProj * vec4(ndc, gl_FragCoord.z, 1.0);
  vec4 far = frame.invViewProj * vec4(ndc, frame.farDepth, 1.0);
  outColor = vec4(self.xyz / self.w - far.xyz / far.w, 1.0);
}
// CHECK: "output": "copied",
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "matrix * vector",
// CHECK-NEXT: "matrix": "frame.invViewProj",
// CHECK-NEXT: "reason": "z is not a depth read from a texture"
// CHECK-NEXT: },
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "matrix * vector",
// CHECK-NEXT: "matrix": "frame.invViewProj",
// CHECK-NEXT: "reason": "z is not a depth read from a texture"
// CHECK-NEXT: },
// The pixel position itself reaches the output other than through an unprojection.
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "gl_FragCoord",
// CHECK-NEXT: "reaches": "outColor",
// CHECK: "result": "unchanged"
