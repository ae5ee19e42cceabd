// halo by value, the reverse: the position is read back from another output. The output gets the
// shift, and the position reads the mono product it was computed from, so stereo-shift shifts it
// once (not the already shifted output a second time). The IR proves `outPos` a copy of the one
// position value and its only store, so the source splice re-copies the shifted position to it; the
// re-emit (--force-reemit) shows the IR form.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json
// RUN: FileCheck %s --check-prefix=SPLICE --input-file %t.vert
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// SPLICE:      {{^}}void main_stereoshift_mono() {
// SPLICE:      gl_Position.x = stereoshift_x;
// SPLICE-NEXT: }
// SPLICE-NEXT: outPos = gl_Position;
// SPLICE-NEXT: }
// RUN: %stereoshift --force-reemit --validate-each --verify %s -o %t.reemit.vert
// RUN: FileCheck %s --input-file %t.reemit.vert
// CHECK: vec4 [[MONO:_[0-9]+]] = ((m.projection * m.view) * m.model) * vec4(inPos, 1.0);
// CHECK: outPos = [[SHIFTED:_[0-9]+]];
// CHECK-NEXT: vec4 [[COPY:_[0-9]+]] = [[MONO]];
// CHECK-NEXT: gl_Position = [[COPY]];
// CHECK-NEXT: if ((stereo.eyeSign != 0.0)
// REPORT: "shifted_outputs": [
// REPORT-NEXT: "outPos"
// REPORT: "route": "glsl-source-splice"
#version 450
layout(set = 0, binding = 0) uniform Matrices { mat4 projection; mat4 view; mat4 model; } m;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outPos;
void main() {
  outPos = m.projection * m.view * m.model * vec4(inPos, 1.0);
  gl_Position = outPos;
}
