// stereoshift-expect: fragment
// D3D11 G-buffer pixel shader: multiple render targets for albedo, normal/roughness and emissive.

Texture2D    AlbedoMap    : register(t0);
Texture2D    NormalMap    : register(t1);
Texture2D    MaterialMap  : register(t2);   // r = roughness, g = metalness, b = emissive mask
SamplerState AnisoSampler : register(s0);

cbuffer MaterialConstants : register(b1)
{
    float3 EmissiveColor;
    float  EmissiveIntensity;
};

struct PSInput
{
    float4 Position  : SV_Position;
    float3 Normal    : TEXCOORD0;
    float3 Tangent   : TEXCOORD1;
    float3 Bitangent : TEXCOORD2;
    float2 UV        : TEXCOORD3;
    float  ViewDepth : TEXCOORD4;
};

struct PSOutput
{
    float4 AlbedoMetal   : SV_Target0;
    float4 NormalRough   : SV_Target1;
    float4 EmissiveDepth : SV_Target2;
};

PSOutput PSMain(PSInput input)
{
    float3 tn = NormalMap.Sample(AnisoSampler, input.UV).xyz * 2.0 - 1.0;
    float3 n = normalize(tn.x * input.Tangent + tn.y * input.Bitangent + tn.z * input.Normal);
    float3 mat = MaterialMap.Sample(AnisoSampler, input.UV).rgb;

    PSOutput output;
    output.AlbedoMetal = float4(AlbedoMap.Sample(AnisoSampler, input.UV).rgb, mat.g);
    output.NormalRough = float4(n * 0.5 + 0.5, mat.r);
    output.EmissiveDepth = float4(EmissiveColor * EmissiveIntensity * mat.b, input.ViewDepth);
    return output;
}
