// --cutoff-epsilon 0 reproduces the driver's exact rule: shift when w != 1.0 (ordered, so a NaN w
// stays unshifted), with no abs() and no tolerance constant.
// RUN: %stereoshift --verify --cutoff-epsilon 0 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --cutoff-epsilon 0 --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK-NOT: abs(
// CHECK: if (gl_Position.w != 1.0)
// CHECK-NEXT: {
// CHECK: gl_Position.x =
// CHECK-NOT: abs(
// SPIRV-NOT: FAbs
// SPIRV: [[W:%[0-9]+]] = OpCompositeExtract %float {{%[0-9]+}} 3
// SPIRV-NEXT: [[C:%[0-9]+]] = OpFOrdNotEqual %bool [[W]] %float_1
// SPIRV-NEXT: OpSelectionMerge [[M:%[0-9]+]] None
// SPIRV-NEXT: OpBranchConditional [[C]]
// SPIRV-NOT: FAbs
