// --target picks the output language; by default it is the input's own (Vulkan GLSL here).
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
// RUN: %stereoshift --verify --target glsl %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
// RUN: %stereoshift --verify --target hlsl %s -o - | %rmchecks | FileCheck %s --check-prefix=HLSL
// RUN: %stereoshift --target spirv %s -o %t.spv
// RUN: spirv-val %t.spv
// RUN: spirv-dis %t.spv | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// DEFAULT: #version 450
// DEFAULT: layout(set = 0, binding = 1, std140) uniform StereoParams
// HLSL-NOT: #version
// HLSL: cbuffer StereoParams : register(b1)
// HLSL: SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
// SPIRV: ; SPIR-V
// SPIRV: OpName %StereoParams "StereoParams"
