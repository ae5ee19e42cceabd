// --fused-shift computes the shift as one fused multiply-add of eyeSign * separation, w - convergence
// and x, in the spliced text as in the re-emitted one.
// RUN: %stereoshift --verify --fused-shift %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify --fused-shift --force-reemit %s -o - | %rmchecks | FileCheck %s --check-prefix=REEMIT
// RUN: %stereoshift --fused-shift --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: precise float stereoshift_x = fma(stereo.eyeSign * stereo.separation, gl_Position.w - stereo.convergence, gl_Position.x);
// CHECK-NEXT: gl_Position.x = stereoshift_x;
// REEMIT: precise float [[S:_[0-9]+]] = stereo.eyeSign * stereo.separation;
// REEMIT-NEXT: precise float [[X:_[0-9]+]] = fma([[S]], {{_[0-9]+}}, gl_Position.x);
// REEMIT-NEXT: gl_Position.x = [[X]];
// SPIRV: OpExtInst %float {{%[0-9]+}} Fma
// SPIRV-NOT: OpFAdd %float
// DEFAULT-NOT: fma(
