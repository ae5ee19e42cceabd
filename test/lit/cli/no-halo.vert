// --no-halo leaves outputs computed from the position before the shift (vClip, vScreenUV) mono;
// by default they are shifted with the position.
// RUN: %stereoshift --verify --no-halo %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
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
// CHECK: vClip = gl_Position;
// CHECK-NEXT: vScreenUV = ((gl_Position.xy / vec2(gl_Position.w)) * 0.5) + vec2(0.5);
// CHECK-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) >
// REPORT: "halo": {
// REPORT-NEXT: "result": "unchanged"
// REPORT-NEXT: },
// DEFAULT: gl_Position = {{_[0-9]+}};
// DEFAULT-NEXT: vec4 [[C:_[0-9]+]] = gl_Position;
// DEFAULT: [[C]].x = ((stereo.eyeSign != 0.0) && ((abs([[C]].w - 1.0) > {{[^)]*}}) && (!isinf([[C]].w)))) ? {{_[0-9]+}} : [[C]].x;
// DEFAULT-NEXT: vClip = [[C]];
// DEFAULT: vScreenUV =
// DEFAULT-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) >
