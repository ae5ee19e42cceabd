// halo by value must not fire on a different matrix: a shadow-map coordinate (DepthBiasMVP * p)
// is not a copy of the position (mvp * p), however alike the two products look.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// The spliced text: the shadow coordinate is written once, in the mono main, and nothing copies
// the shifted position into it after the shift.
// CHECK: void main_stereoshift_mono() {
// CHECK-NEXT: outShadowCoord = scene.depthBiasMVP * vec4(inPos, 1.0);
// CHECK-NEXT: gl_Position = scene.mvp * vec4(inPos, 1.0);
// CHECK: main_stereoshift_mono();
// CHECK-NEXT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
// CHECK: gl_Position.x = stereoshift_x;
// CHECK-NOT: outShadowCoord
// REPORT: "halo": {
// REPORT-NEXT: "result": "unchanged",
// REPORT-NEXT: "shifted_outputs": []
#version 450
layout(set = 0, binding = 0) uniform Scene { mat4 mvp; mat4 depthBiasMVP; } scene;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outShadowCoord;
void main() {
  outShadowCoord = scene.depthBiasMVP * vec4(inPos, 1.0);
  gl_Position = scene.mvp * vec4(inPos, 1.0);
}
