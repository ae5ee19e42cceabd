// --no-halo leaves outputs computed from the position before the shift (vClip, vScreenUV) mono;
// by default they are shifted with the position.
// RUN: %stereoshift --verify --no-halo %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// By default vScreenUV (derived from the position, not a copy) needs the IR: re-emitted, with a note.
// RUN: %stereoshift --verify %s -o - 2>%t.notes | %rmchecks | FileCheck %s --check-prefix=DEFAULT
// RUN: FileCheck %s --check-prefix=NOTE --input-file %t.notes
// NOTE: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the halo pass changed the output 'vScreenUV', which
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec4 vClip;
layout(location = 1) out vec2 vScreenUV;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
  vClip = gl_Position;
  vScreenUV = gl_Position.xy / gl_Position.w * 0.5 + 0.5;
}
// The spliced text: the outputs keep the mono position, nothing re-copies them after the shift.
// CHECK: vClip = gl_Position;
// CHECK-NEXT: vScreenUV = gl_Position.xy / gl_Position.w * 0.5 + 0.5;
// CHECK: main_stereoshift_mono();
// CHECK-NEXT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
// CHECK-NOT: vClip =
// CHECK-NOT: vScreenUV =
// REPORT: "halo": {
// REPORT-NEXT: "result": "unchanged"
// REPORT-NEXT: },
// DEFAULT: gl_Position = {{_[0-9]+}};
// DEFAULT-NEXT: vec4 [[C:_[0-9]+]] = gl_Position;
// DEFAULT: [[C]].x = ((stereo.eyeSign != 0.0) && ((abs([[C]].w - 1.0) > {{[^)]*}}) && (!isinf([[C]].w)))) ? {{_[0-9]+}} : [[C]].x;
// DEFAULT-NEXT: vClip = [[C]];
// DEFAULT: vScreenUV =
// DEFAULT-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) >
