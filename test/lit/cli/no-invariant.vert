// --no-invariant leaves the position without the invariant qualifier and the shift without NoContraction;
// by default the shift has it (a precise temporary in the spliced text, which adds no qualifier to
// the interface), and the IR (SPIR-V, the re-emit) marks the position invariant too.
// RUN: %stereoshift --verify --no-invariant %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify --no-invariant --force-reemit %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --no-invariant --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: #version 450
// CHECK-NOT: invariant
// CHECK-NOT: precise
// CHECK: stereo.eyeSign * stereo.separation
// CHECK-NOT: precise
// SPIRV-NOT: NoContraction
// SPIRV-NOT: Invariant
// SPIRV: OpFAdd %float
// RUN: %stereoshift --verify --force-reemit %s -o - | %rmchecks | FileCheck %s --check-prefix=REEMIT
// DEFAULT: #version 450
// DEFAULT-NOT: invariant
// DEFAULT: precise float stereoshift_x =
// REEMIT: invariant gl_Position;
// REEMIT: precise float
