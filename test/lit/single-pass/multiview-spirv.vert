// --eye-source multiview to SPIR-V: the MultiView capability (SPV_KHR_multiview) and a ViewIndex
// built-in input in the interface; the module validates for Vulkan 1.0.
// RUN: %stereoshift --eye-source multiview --target spirv %s -o %t.spv
// RUN: spirv-val --target-env vulkan1.0 %t.spv
// RUN: spirv-dis %t.spv | FileCheck %s
// REQUIRES: spirv-dis, spirv-val
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: OpCapability MultiView
// CHECK: OpExtension "SPV_KHR_multiview"
// CHECK: OpEntryPoint Vertex %main "main" {{.*}}%gl_ViewIndex
// CHECK: OpDecorate %gl_ViewIndex BuiltIn ViewIndex
// CHECK: %gl_ViewIndex = OpVariable %_ptr_Input_int Input
