// Entry-point inputs declared without a name (kept for their place in the input layout, never
// read): HLSL allows them and glslang's HLSL parser crashed on them, losing the shader. They are
// named for the parse only; the output is the input, its signature in the order written, plus the
// shift (the parameter list below is matched whole), and verify runs it.
// RUN: %stereoshift %s -o %t.hlsl
// RUN: %rmchecks %t.hlsl | FileCheck %s
// RUN: %stereoshift verify %s | FileCheck %s --check-prefix=VERIFY
// CHECK: VSOut main(float3 position : POSITION, float3 : NORMAL, in vector<float, 4> : COLOR0, float2 uv : TEXCOORD0, uint : SV_VertexID)
// CHECK: return stereoshift_shift_VSOut(o);
// CHECK-NOT: stereoshift_unnamed
// VERIFY: verified
cbuffer Camera : register(b0)
{
  float4x4 worldViewProj;
};

struct VSOut
{
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
};

VSOut main(float3 position : POSITION, float3 : NORMAL, in vector<float, 4> : COLOR0, float2 uv : TEXCOORD0, uint : SV_VertexID)
{
  VSOut o;
  o.pos = mul(worldViewProj, float4(position, 1));
  o.uv = uv;
  return o;
}
