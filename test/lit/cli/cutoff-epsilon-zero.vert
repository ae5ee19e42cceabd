// --cutoff-epsilon 0 reproduces the driver's exact rule: shift when w != 1.0 (ordered, so a NaN w
// stays unshifted; an infinite w too), with no absolute value and no tolerance constant.
// RUN: %stereoshift --verify --cutoff-epsilon 0 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --cutoff-epsilon 0 --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK-NOT: abs(
// CHECK: if (stereo.eyeSign != 0.0 && gl_Position.w != 1.0 && !isinf(gl_Position.w))
// CHECK-NEXT: {
// CHECK: gl_Position.x =
// CHECK-NOT: abs(
// SPIRV-NOT: FAbs
// SPIRV: [[W:%[0-9]+]] = OpCompositeExtract %float {{%[0-9]+}} 3
// SPIRV: [[E:%[0-9]+]] = OpFUnordNotEqual %bool {{%[0-9]+}} %float_0
// SPIRV-NEXT: [[C:%[0-9]+]] = OpFOrdNotEqual %bool [[W]] %float_1
// SPIRV-NEXT: [[INF:%[0-9]+]] = OpIsInf %bool [[W]]
// SPIRV-NEXT: [[FINITE:%[0-9]+]] = OpLogicalNot %bool [[INF]]
// SPIRV-NEXT: [[WG:%[0-9]+]] = OpLogicalAnd %bool [[C]] [[FINITE]]
// SPIRV-NEXT: [[G:%[0-9]+]] = OpLogicalAnd %bool [[E]] [[WG]]
// SPIRV-NEXT: OpSelectionMerge [[M:%[0-9]+]] None
// SPIRV-NEXT: OpBranchConditional [[G]]
// SPIRV-NOT: FAbs
