// --no-invariant leaves the position without `invariant` and the shift without `precise`
// (NoContraction); by default both are there.
// RUN: %stereoshift --verify --no-invariant %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --no-invariant --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK-NOT: invariant
// CHECK-NOT: precise
// CHECK: stereo.eyeSign * stereo.separation
// CHECK-NOT: precise
// SPIRV-NOT: NoContraction
// SPIRV-NOT: Invariant
// SPIRV: OpFAdd %float
// DEFAULT: invariant gl_Position;
// DEFAULT: precise float
