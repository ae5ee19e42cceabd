// --no-halo leaves outputs computed from the position before the shift (vClip, vScreenUV) mono;
// by default they are shifted with the position.
// RUN: %stereoshift --verify --no-halo %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// By default vScreenUV (derived from the position, not a copy) reads it, in the spliced text, through
// the shift; vClip (a copy) is re-copied after the shift.
// RUN: %stereoshift --verify %s -o - 2>%t.notes | %rmchecks | FileCheck %s --check-prefix=DEFAULT
// RUN: FileCheck %s --check-prefix=NOTE --allow-empty --input-file %t.notes
// NOTE-NOT: re-emitted
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
// DEFAULT: vClip = gl_Position;
// DEFAULT-NEXT: vScreenUV = stereoshift_shifted_position(gl_Position).xy / stereoshift_shifted_position(gl_Position).w * 0.5 + 0.5;
// DEFAULT: vec4 stereoshift_shifted_position(vec4 stereoshift_p)
// DEFAULT: main_stereoshift_mono();
// DEFAULT: gl_Position.x = stereoshift_x;
// DEFAULT: vClip = gl_Position;
// DEFAULT-NEXT: }
