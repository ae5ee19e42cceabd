// --shift-form select codes the cutoff branch-free: x = cond ? shifted : x, no if/selection merge.
// RUN: %stereoshift --verify --shift-form select %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --shift-form select --target spirv-asm %s -o - --report %t.json | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift --verify --shift-form branch %s -o - | %rmchecks | FileCheck %s --check-prefix=BRANCH
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: void main()
// CHECK-NOT: if (
// CHECK: precise float stereoshift_x = (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w)) ? gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence) : gl_Position.x;
// CHECK-NEXT: gl_Position.x = stereoshift_x;
// CHECK-NOT: if (
// SPIRV-NOT: OpSelectionMerge
// SPIRV: [[FAR:%[0-9]+]] = OpFOrdGreaterThan %bool
// SPIRV-NEXT: OpIsInf %bool
// SPIRV-NEXT: OpLogicalNot %bool
// SPIRV-NEXT: [[WG:%[0-9]+]] = OpLogicalAnd %bool [[FAR]]
// SPIRV-NEXT: [[COND:%[0-9]+]] = OpLogicalAnd %bool {{%[0-9]+}} [[WG]]
// SPIRV-NEXT: [[SEL:%[0-9]+]] = OpSelect %float [[COND]]
// SPIRV-NEXT: [[NEW:%[0-9]+]] = OpCompositeInsert %v4float [[SEL]] {{%[0-9]+}} 0
// SPIRV-NEXT: OpStore {{%[0-9]+}} [[NEW]]
// SPIRV-NOT: OpSelectionMerge
// REPORT: "form": "select",
// BRANCH: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
