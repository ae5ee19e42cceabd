// A D3D12 view-instancing vertex shader reads SV_ViewID: stereo already, copied unchanged.
// RUN: %stereoshift %s -S vert -o %t.hlsl --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: cmp %s %t.hlsl
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// NOTE: note: shader reads the view index {{.*}} never shifted twice
// REPORT: "classification": "already-stereo"
cbuffer PerView : register(b0) { float4x4 ViewProj[2]; };
cbuffer PerObject : register(b1) { float4x4 World; };
struct VSOut { float4 pos : SV_Position; float3 normal : NORMAL; };
VSOut main(float3 pos : POSITION, float3 normal : NORMAL, uint view : SV_ViewID) {
  VSOut o;
  o.pos = mul(ViewProj[view], mul(World, float4(pos, 1.0)));
  o.normal = normal;
  return o;
}
