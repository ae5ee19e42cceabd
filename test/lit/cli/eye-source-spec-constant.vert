// --eye-source=spec-constant makes the eye parameters specialization constants (SpecIds 100-102,
// mono defaults eyeSign 0, separation 0, convergence 1) so a build can bake left/right variants.
// RUN: %stereoshift --verify --eye-source spec-constant %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --eye-source spec-constant --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK-NOT: StereoParams
// CHECK: layout(constant_id = 100) const float eyeSign = 0.0;
// CHECK-NEXT: layout(constant_id = 101) const float separation = 0.0;
// CHECK-NEXT: layout(constant_id = 102) const float convergence = 1.0;
// CHECK-NOT: StereoParams
// CHECK: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK: precise float stereoshift_x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// SPIRV-DAG: OpDecorate %eyeSign SpecId 100
// SPIRV-DAG: OpDecorate %separation SpecId 101
// SPIRV-DAG: OpDecorate %convergence SpecId 102
// SPIRV-DAG: %eyeSign = OpSpecConstant %float 0
// SPIRV-DAG: %separation = OpSpecConstant %float 0
// SPIRV-DAG: %convergence = OpSpecConstant %float 1
// SPIRV: OpFMul %float %eyeSign %separation
