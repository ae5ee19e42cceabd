// halo by value, the reverse: the position is read back from another output. The output gets the
// shift, and the position reads the mono product it was computed from, so stereo-shift shifts it
// once (not the already shifted output a second time). The text has no plain `outPos = gl_Position;`
// copy the source splice could repeat, so the output is SPIRV-Cross's re-emit, with a note.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json 2>%t.notes
// RUN: FileCheck %s --check-prefix=NOTE --input-file %t.notes
// NOTE: halo-read-back.vert: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the halo copy 'outPos' of the clip position is not a plain `outPos = gl_Position;` in the text
// RUN: FileCheck %s --input-file %t.vert
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK: vec4 [[MONO:_[0-9]+]] = ((m.projection * m.view) * m.model) * vec4(inPos, 1.0);
// CHECK: outPos = [[SHIFTED:_[0-9]+]];
// CHECK-NEXT: vec4 [[COPY:_[0-9]+]] = [[MONO]];
// CHECK-NEXT: gl_Position = [[COPY]];
// CHECK-NEXT: if ((stereo.eyeSign != 0.0)
// REPORT: "shifted_outputs": [
// REPORT-NEXT: "outPos"
#version 450
layout(set = 0, binding = 0) uniform Matrices { mat4 projection; mat4 view; mat4 model; } m;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outPos;
void main() {
  outPos = m.projection * m.view * m.model * vec4(inPos, 1.0);
  gl_Position = outPos;
}
