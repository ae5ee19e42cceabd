// --fused-shift computes the shift as one fma(eyeSign * separation, w - convergence, x).
// RUN: %stereoshift --verify --fused-shift %s -o - | FileCheck %s
// RUN: %stereoshift --fused-shift --target spirv-asm %s -o - | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift %s -o - | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: precise float [[S:_[0-9]+]] = stereo.eyeSign * stereo.separation;
// CHECK-NEXT: precise float [[X:_[0-9]+]] = fma([[S]], {{_[0-9]+}}, gl_Position.x);
// CHECK-NEXT: gl_Position.x = [[X]];
// SPIRV: OpExtInst %float {{%[0-9]+}} Fma
// SPIRV-NOT: OpFAdd %float
// DEFAULT-NOT: fma(
