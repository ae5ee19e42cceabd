// stereoshift-expect: fragment
// D3D11 instanced foliage pixel shader: alpha-clipped leaves with two-sided translucency.

cbuffer FoliageLighting : register(b1)
{
    float3 SunDirection;
    float  AlphaCutoff;
    float3 SunColor;
    float  Translucency;
};

Texture2D    LeafTexture : register(t1);
SamplerState LeafSampler : register(s0);

struct PSInput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
    float3 Tint     : COLOR0;
    bool   FrontFace : SV_IsFrontFace;
};

float4 PSMain(PSInput input) : SV_Target
{
    float4 leaf = LeafTexture.Sample(LeafSampler, input.UV);
    clip(leaf.a - AlphaCutoff);
    float3 n = normalize(input.FrontFace ? input.Normal : -input.Normal);
    float front = saturate(dot(n, -SunDirection));
    float back = saturate(dot(-n, -SunDirection)) * Translucency;
    float3 color = leaf.rgb * input.Tint * SunColor * (0.25 + front + back);
    return float4(color, 1.0);
}
