// stereoshift-expect: fragment
// D3D11 mesh-explosion pixel shader: diffuse texture modulated by the shard colour with an emissive edge glow.

cbuffer ShardShading : register(b2)
{
    float3 LightDirection;
    float  GlowAmount;
    float3 GlowColor;
    float  Padding;
};

Texture2D    DiffuseMap  : register(t0);
SamplerState WrapSampler : register(s0);

struct PSInput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
    float4 Color    : COLOR0;
};

float4 PSMain(PSInput input) : SV_Target
{
    float3 base = DiffuseMap.Sample(WrapSampler, input.UV).rgb * input.Color.rgb;
    float ndl = saturate(dot(normalize(input.Normal), -LightDirection));
    float3 glow = GlowColor * GlowAmount * (1.0 - input.Color.g);
    return float4(base * (0.2 + 0.8 * ndl) + glow, 1.0);
}
