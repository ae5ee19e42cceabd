// An HLSL SM5 vertex shader with struct in/out stays a drop-in replacement: its own text, so the
// input and output structs keep their members, order and semantics (D3D links the pixel shader's
// inputs by register), the cbuffer keeps its register and member names, the entry point its name;
// the eye parameters go into a cbuffer at the next free register and the return is shifted.
// RUN: %stereoshift --verify %s -o %t.out.hlsl
// RUN: %rmchecks %t.out.hlsl | FileCheck %s
// RUN: %rmchecks %t.out.hlsl | FileCheck %s --check-prefix=NEG
// RUN: glslangValidator -D -V -S vert -e VSMain -o %t.spv %t.out.hlsl

cbuffer Frame : register(b0)
{
  float4x4 WorldViewProj;
  float4x4 World;
};

struct VSInput
{
  float3 Position : POSITION;
  float3 Normal : NORMAL;
  float2 UV : TEXCOORD0;
};

struct VSOutput
{
  float4 Position : SV_Position;
  float3 Normal : NORMAL;
  float2 UV : TEXCOORD0;
};

VSOutput VSMain(VSInput input)
{
  VSOutput output;
  output.Position = mul(WorldViewProj, float4(input.Position, 1.0));
  output.Normal = mul((float3x3)World, input.Normal);
  output.UV = input.UV;
  return output;
}
// CHECK: cbuffer Frame : register(b0)
// CHECK-NEXT: {
// CHECK-NEXT: float4x4 WorldViewProj;
// CHECK-NEXT: float4x4 World;
// CHECK-NEXT: };
// CHECK: struct VSOutput
// CHECK-NEXT: {
// CHECK-NEXT: float4 Position : SV_Position;
// CHECK-NEXT: float3 Normal : NORMAL;
// CHECK-NEXT: float2 UV : TEXCOORD0;
// CHECK-NEXT: };
// CHECK: cbuffer StereoParams : register(b1)
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: };
// CHECK: if (eyeSign != 0.0f && abs(stereoshift_v.Position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Position.w))
// CHECK: precise float stereoshift_x = stereoshift_v.Position.x + (eyeSign * separation)
// CHECK: VSOutput VSMain(VSInput input)
// CHECK: return stereoshift_shift_VSOutput(output);
// NEG-NOT: SPIRV_Cross
// NEG-NOT: {{ main\(}}
