// stereoshift-expect: fragment
// D3D11 forward-lit pixel shader: two directional lights with Lambert diffuse and a tinted albedo texture.

cbuffer Lighting : register(b1)
{
    float3 KeyLightDir;
    float  KeyIntensity;
    float3 FillLightDir;
    float  FillIntensity;
    float3 AmbientColor;
    float  Padding;
};

Texture2D    AlbedoTexture : register(t0);
SamplerState LinearSampler : register(s0);

struct PSInput
{
    float4 Position : SV_Position;
    float3 WorldNormal : TEXCOORD0;
    float2 UV : TEXCOORD1;
    float4 Tint : COLOR0;
};

float4 PSMain(PSInput input) : SV_Target
{
    float3 n = normalize(input.WorldNormal);
    float key = saturate(dot(n, -KeyLightDir)) * KeyIntensity;
    float fill = saturate(dot(n, -FillLightDir)) * FillIntensity;
    float4 albedo = AlbedoTexture.Sample(LinearSampler, input.UV) * input.Tint;
    return float4(albedo.rgb * (AmbientColor + key + fill), albedo.a);
}
