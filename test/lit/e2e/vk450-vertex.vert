// A Vulkan GLSL vertex shader comes back as its own text: main renamed, the StereoParams block
// (the binding after the shader's own) and the shifting main appended; no invariant qualifier
// is added to the interface (the shift is a precise temporary).
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s
// CHECK: #version 450
// CHECK-NOT: invariant
// CHECK: layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
// CHECK-NEXT: layout(location = 0) in vec3 inPosition;
// CHECK-NEXT: void main_stereoshift_mono() {
// CHECK-NEXT: gl_Position = camera.viewProj * vec4(inPosition, 1.0);
// CHECK-NEXT: }
// CHECK-NEXT: // ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// CHECK-NEXT: layout(set = 0, binding = 1, std140) uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } stereo;
// CHECK-NEXT: void main()
// CHECK-NEXT: {
// CHECK-NEXT: main_stereoshift_mono();
// CHECK-NEXT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NEXT: {
// CHECK-NEXT: precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
// CHECK-NEXT: gl_Position.x = stereoshift_x;
// CHECK-NEXT: }
// CHECK-NEXT: }
// CHECK-NEXT: // ---- end stereoshift ----
// CHECK-NOT: invariant
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
