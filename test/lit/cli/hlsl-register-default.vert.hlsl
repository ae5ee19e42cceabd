// Without --hlsl-register the injected cbuffer takes the register one past the highest used, as
// --help says: b3 here, not the hole at b1 (an application may bind something there later).
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s
cbuffer Frame : register(b0) { float4x4 ViewProj; };
cbuffer Object : register(b2) { float4x4 World; };
float4 main(float3 pos : POSITION) : SV_Position
{
  return mul(ViewProj, mul(World, float4(pos, 1.0)));
}
// CHECK: cbuffer StereoParams : register(b3)
