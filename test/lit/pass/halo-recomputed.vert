// halo by value: an output that recomputes the clip position (the same product, written with the
// components spelled out) and one derived from the product computed again in a helper function are
// both the position: each gets the shift the position gets (a select on the same cutoff). The
// recomputation is an exact copy by value (what the HLSL splice may copy); the screen UV is derived,
// which only the IR carries: the GLSL output is SPIRV-Cross's re-emit, with a note.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json 2>%t.notes
// RUN: FileCheck %s --check-prefix=NOTE --input-file %t.notes
// NOTE: halo-recomputed.vert: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the halo pass changed the output 'outScreenUV', which is computed from the clip position (not a copy of it), and only the IR carries that
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
