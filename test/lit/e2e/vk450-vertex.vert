// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s
#version 450
// CHECK: #version 450
// CHECK-DAG: invariant gl_Position;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
// CHECK-DAG: layout(set = 0, binding = 0, std140) uniform Camera
// CHECK: layout(set = 0, binding = 1, std140) uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } stereo;
layout(location = 0) in vec3 inPosition;
// CHECK: layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
// CHECK: void main()
// CHECK: camera.viewProj *
// CHECK: gl_Position =
// CHECK-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(gl_Position.w))))
// CHECK-NEXT: {
// CHECK: gl_Position.x = {{.*}}
// CHECK-NEXT: }
// CHECK-NEXT: }
}
