// --eye-source=push-constant in a shader without a push-constant block declares a new one
// (no descriptor set or binding).
// RUN: %stereoshift --verify --eye-source push-constant %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --eye-source push-constant --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: layout(push_constant) uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } stereo;
// CHECK: precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
// SPIRV-NOT: OpDecorate %stereo DescriptorSet
// SPIRV-NOT: OpDecorate %stereo Binding
// SPIRV: %_ptr_PushConstant_StereoParams = OpTypePointer PushConstant %StereoParams
// SPIRV: %stereo = OpVariable %_ptr_PushConstant_StereoParams PushConstant
// SPIRV: OpAccessChain %_ptr_PushConstant_float %stereo %int_0
