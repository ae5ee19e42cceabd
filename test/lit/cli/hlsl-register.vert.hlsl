// --hlsl-register puts the injected cbuffer in register b<N>.
// RUN: %stereoshift --verify --hlsl-register 5 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
cbuffer Frame : register(b0) { float4x4 ViewProj; };
Texture2D HeightMap : register(t1);
SamplerState LinearSampler : register(s1);
float4 main(float3 pos : POSITION, float2 uv : TEXCOORD0) : SV_Position
{
  float h = HeightMap.SampleLevel(LinearSampler, uv, 0).r;
  return mul(ViewProj, float4(pos + float3(0, h, 0), 1.0));
}
// CHECK: cbuffer Frame : register(b0)
// CHECK: Texture2D HeightMap : register(t1);
// CHECK: SamplerState LinearSampler : register(s1);
// CHECK: cbuffer StereoParams : register(b5)
// Textures and samplers (t1, s1) do not take constant-buffer registers.
// DEFAULT: cbuffer StereoParams : register(b1)
