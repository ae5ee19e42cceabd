// Near miss (HLSL): tangent-space normal mapping weights three interpolated vectors by the
// components of one texel, `tn.x * T + tn.y * B + tn.z * N`. Each term looks like a vector times a
// texel, but one texture weighting vectors from several inputs is a basis, not a view ray meeting
// its depth: left as it is.
// RUN: %stereoshift --validate-each %s -e PSMain --report %t.json -o %t.out.hlsl
// RUN: cmp %s %t.out.hlsl
// RUN: FileCheck %s --input-file %t.json
Texture2D NormalMap : register(t0);
SamplerState LinearWrap : register(s0);
struct PSInput
{
    float4 Position : SV_Position;
    float3 Normal : TEXCOORD0;
    float3 Tangent : TEXCOORD1;
    float3 Bitangent : TEXCOORD2;
    float2 UV : TEXCOORD3;
};
float4 PSMain(PSInput input) : SV_Target
{
    float3 tn = NormalMap.Sample(LinearWrap, input.UV).xyz * 2.0 - 1.0;
    float3 n = normalize(tn.x * input.Tangent + tn.y * input.Bitangent + tn.z * input.Normal);
    return float4(n * 0.5 + 0.5, 1.0);
}
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "result": "unchanged"
