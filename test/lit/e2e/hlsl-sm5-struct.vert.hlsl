// An HLSL SM5 vertex shader with struct in/out stays a drop-in replacement: the semantics of the
// input layout and of the vertex-to-pixel interface, the cbuffer and its register, unprefixed
// member names, and the entry-point name; the eye parameters go into a cbuffer at the next free
// register.
// RUN: %stereoshift --verify %s -o %t.out.hlsl
// RUN: %rmchecks %t.out.hlsl | FileCheck %s
// RUN: %rmchecks %t.out.hlsl | FileCheck %s --check-prefix=NEG
// RUN: glslangValidator -D -V -S vert -e VSMain -o %t.spv %t.out.hlsl

cbuffer Frame : register(b0)
{
  float4x4 WorldViewProj;
  float4x4 World;
};
// CHECK: cbuffer Frame : register(b0)
// CHECK-NEXT: {
// CHECK-NEXT: float4x4 WorldViewProj : packoffset(c0);
// CHECK-NEXT: float4x4 World : packoffset(c4);
// CHECK-NEXT: };
// CHECK: cbuffer StereoParams : register(b1)
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign : packoffset(c0);
// CHECK-NEXT: float separation : packoffset(c0.y);
// CHECK-NEXT: float convergence : packoffset(c0.z);
// CHECK-NEXT: };

struct VSInput
{
  float3 Position : POSITION;
  float3 Normal : NORMAL;
  float2 UV : TEXCOORD0;
};
// CHECK: struct SPIRV_Cross_Input
// CHECK-NEXT: {
// CHECK-NEXT: float3 {{[A-Za-z_]+}} : POSITION;
// CHECK-NEXT: float3 {{[A-Za-z_]+}} : NORMAL;
// CHECK-NEXT: float2 {{[A-Za-z_]+}} : TEXCOORD0;
// CHECK-NEXT: };

struct VSOutput
{
  float4 Position : SV_Position;
  float3 Normal : NORMAL;
  float2 UV : TEXCOORD0;
};
// CHECK: struct SPIRV_Cross_Output
// CHECK-NEXT: {
// CHECK-DAG: float3 {{[A-Za-z_]+}} : NORMAL;
// CHECK-DAG: float2 {{[A-Za-z_]+}} : TEXCOORD0;
// CHECK-DAG: float4 {{[A-Za-z_]+}} : SV_Position;
// CHECK: };

VSOutput VSMain(VSInput input)
{
  VSOutput output;
  output.Position = mul(WorldViewProj, float4(input.Position, 1.0));
  output.Normal = mul((float3x3)World, input.Normal);
  output.UV = input.UV;
  return output;
}
// CHECK: mul(WorldViewProj,
// CHECK: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0f) > {{9\.9999997[0-9]*e-0*6}}f) && (!isinf(gl_Position.w))))
// CHECK: precise float {{_[0-9]+}} = eyeSign * separation;
// CHECK: gl_Position.x =
// CHECK: SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)

// SPIRV-Cross would rename cbuffer members <instance>_<member> and call the entry point main.
// NEG-NOT: {{_[0-9]+_World}}
// NEG-NOT: {{[A-Za-z]+_WorldViewProj}}
// NEG-NOT: {{ main\(}}
// NEG: SPIRV_Cross_Output VSMain(
