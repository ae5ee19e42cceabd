// --instance-name renames the injected block's instance; the shift reads through it.
// RUN: %stereoshift --verify --instance-name eye %s -o - | %rmchecks | FileCheck %s
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } eye;
// CHECK: if (eye.eyeSign != 0.0
// CHECK: precise float stereoshift_x = gl_Position.x + (eye.eyeSign * eye.separation) * (gl_Position.w - eye.convergence);
// CHECK-NOT: stereo.
