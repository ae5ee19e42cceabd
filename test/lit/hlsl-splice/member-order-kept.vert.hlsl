// The vertex output struct keeps its members in the order written, SV_Position in the middle
// included, with their semantics and attributes: D3D links the unchanged pixel shader's inputs
// by register in declaration order. No SPIRV-Cross struct appears.
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s
// CHECK: struct VSOut
// CHECK-NEXT: {
// CHECK-NEXT: float3 normal : NORMAL;
// CHECK-NEXT: float4 position : SV_Position;
// CHECK-NEXT: {{\[\[}}vk::location(1)]] float2 uv : TEXCOORD0;
// CHECK-NEXT: };
// CHECK: VSOut VSMain(float3 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0)
// CHECK: return stereoshift_shift_VSOut(o);
// CHECK-NOT: SPIRV_Cross
cbuffer Camera : register(b0) { float4x4 ViewProj; };

struct VSOut
{
    float3 normal : NORMAL;
    float4 position : SV_Position;
    [[vk::location(1)]] float2 uv : TEXCOORD0;
};

VSOut VSMain(float3 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0)
{
    VSOut o;
    o.normal = n;
    o.position = mul(ViewProj, float4(p, 1.0));
    o.uv = uv;
    return o;
}
