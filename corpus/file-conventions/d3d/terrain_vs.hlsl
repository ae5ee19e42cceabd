// stereoshift-expect: shift
// Book-style vertex shader named `*_vs.hlsl`: a height-mapped terrain grid, entry point VSMain.
cbuffer TerrainConstants : register(b0)
{
    float4x4 WorldViewProj;
    float HeightScale;
    float3 Padding;
};
Texture2D HeightMap : register(t0);
SamplerState PointClamp : register(s0);

struct VertexOut
{
    float4 PosH : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

VertexOut VSMain(float3 posL : POSITION, float2 tex : TEXCOORD0)
{
    VertexOut vout;
    float height = HeightMap.SampleLevel(PointClamp, tex, 0).r * HeightScale;
    vout.PosH = mul(float4(posL.x, height, posL.z, 1.0f), WorldViewProj);
    vout.Tex = tex;
    return vout;
}
