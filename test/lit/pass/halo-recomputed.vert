// halo by value: an output that recomputes the clip position (the same product, written with the
// components spelled out) and one derived from the product computed again in a helper function are
// both the position: each gets the shift the position gets (a select on the same cutoff). The
// recomputation is an exact copy by value (re-copied from the shifted position by the splice); the
// screen UV is derived from a local the analysis found to hold the position by value, so in the
// spliced text its reads of that local go through stereoshift_shifted_position().
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json 2>%t.notes
// RUN: FileCheck %s --check-prefix=NOTE --allow-empty --input-file %t.notes
// NOTE-NOT: re-emitted
// RUN: %rmchecks %t.vert | FileCheck %s --check-prefix=TEXT
// TEXT: outScreenUV = stereoshift_shifted_position(again).xy / stereoshift_shifted_position(again).w * 0.5 + 0.5;
// TEXT: main_stereoshift_mono();
// TEXT: outClip = gl_Position;
// RUN: FileCheck %s --input-file %t.json
// CHECK: "halo": {
// CHECK-NEXT: "derived_outputs": [
// CHECK-NEXT: "outScreenUV"
// CHECK-NEXT: ],
// CHECK-NEXT: "result": "changed",
// CHECK-NEXT: "shifted_outputs": [
// CHECK-NEXT: "outClip",
// CHECK-NEXT: "outScreenUV"
// CHECK-NEXT: ]
#version 450
layout(set = 0, binding = 0) uniform Scene { mat4 mvp; } scene;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outClip;
layout(location = 1) out vec2 outScreenUV;
vec4 toClip(vec3 p) { return scene.mvp * vec4(p, 1.0); }
void main() {
  outClip = scene.mvp * vec4(inPos.x, inPos.y, inPos.z, 1.0);
  vec4 again = toClip(inPos);
  outScreenUV = again.xy / again.w * 0.5 + 0.5;
  gl_Position = scene.mvp * vec4(inPos, 1.0);
}
