// One Vulkan GLSL input, every output language: each keeps the StereoParams parameters and the
// guarded shift in that language's own form (GLSL, the input's own language, is the original text
// plus the splice's edits; the others are written by SPIRV-Cross).
// RUN: %stereoshift --verify --target glsl %s -o - | %rmchecks | FileCheck %s --check-prefix=GLSL
// RUN: %stereoshift --verify --target essl %s -o - | %rmchecks | FileCheck %s --check-prefix=ESSL
// RUN: %stereoshift --verify --target hlsl %s -o - | %rmchecks | FileCheck %s --check-prefix=HLSL
// RUN: %stereoshift --verify --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPVASM
// RUN: %stereoshift --verify --target spirv %s -o %t.spv
// RUN: spirv-val %t.spv
// RUN: spirv-dis %t.spv | FileCheck %s --check-prefix=SPVASM
#version 450
// GLSL: #version 450
// ESSL: #version 310 es
// SPVASM: OpEntryPoint Vertex %main "main"
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
// GLSL: layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
// ESSL: layout(binding = 0, std140) uniform Camera
// ESSL: layout(binding = 1, std140) uniform StereoParams
// HLSL: cbuffer Camera : register(b0)
// HLSL: cbuffer StereoParams : register(b1)
// SPVASM-DAG: OpDecorate %StereoParams Block
// SPVASM-DAG: OpDecorate %stereo Binding 1
// SPVASM-DAG: OpMemberDecorate %gl_PerVertex 0 Invariant
layout(location = 0) in vec3 inPosition;
// GLSL: layout(location = 0) in vec3 inPosition;
// ESSL: layout(location = 0) in vec3 inPosition;
// HLSL: float3 inPosition : TEXCOORD0;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// GLSL: layout(set = 0, binding = 1, std140) uniform StereoParams
// GLSL: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// GLSL: precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
// GLSL: gl_Position.x = stereoshift_x;
// ESSL does not have `precise` before 320: the shift is plain float arithmetic.
// ESSL: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(gl_Position.w))))
// ESSL: {{^ *}}float {{_[0-9]+}} = stereo.eyeSign * stereo.separation;
// ESSL: gl_Position.x =
// HLSL: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0f) > {{9\.9999997[0-9]*e-0*6}}f) && (!isinf(gl_Position.w))))
// HLSL: precise float {{_[0-9]+}} = eyeSign * separation;
// HLSL: gl_Position.x =
// HLSL: SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
// SPVASM: OpFOrdGreaterThan %bool {{%[0-9]+}} %float_9_99999975en06
// SPVASM-NEXT: OpIsInf %bool
// SPVASM-NEXT: OpLogicalNot %bool
// SPVASM-NEXT: OpLogicalAnd %bool
// SPVASM-NEXT: OpLogicalAnd %bool
// SPVASM-NEXT: OpSelectionMerge
// SPVASM: OpFAdd %float
