// An HLSL vertex shader converted twice is left as it is the second time.
// RUN: %stereoshift --verify %s -o %t.1.vert.hlsl
// RUN: %stereoshift --verify %t.1.vert.hlsl -o %t.2.vert.hlsl 2>&1 | FileCheck %s
// RUN: cmp %t.1.vert.hlsl %t.2.vert.hlsl
// CHECK: note: shader already carries stereo eye parameters ('eyeSign'); left as it is, never shifted twice
cbuffer Frame : register(b0) { float4x4 ViewProj; };
float4 VSMain(float3 pos : POSITION) : SV_Position
{
  return mul(ViewProj, float4(pos, 1.0));
}
