// RUN: %stereoshift --verify %s -o - | FileCheck %s
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: #version 450
// CHECK: layout(set = 0, binding = 0, std140) uniform Camera
// CHECK: layout(set = 0, binding = 1, std140) uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } stereo;
// CHECK: invariant gl_Position;
// CHECK: layout(location = 0) in vec3 inPosition;
// CHECK: gl_Position = camera.viewProj * vec4(inPosition, 1.0);
// CHECK: if (abs(gl_Position.w - 1.0) > 9.99999974737875163555145263671875e-06)
// CHECK: gl_Position.x = {{.*}}stereo.eyeSign * stereo.separation{{.*}}gl_Position.w - stereo.convergence
