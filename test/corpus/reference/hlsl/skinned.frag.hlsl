// stereoshift-expect: fragment
// D3D11 skinned-mesh pixel shader: toon-ramp shading for characters.

cbuffer ToonConstants : register(b2)
{
    float3 LightDirection;
    float  RimStrength;
    float4 BaseColor;
};

Texture2D    DiffuseTexture : register(t0);
Texture2D    RampTexture    : register(t1);
SamplerState WrapSampler    : register(s0);
SamplerState ClampSampler   : register(s1);

struct PSInput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

float4 main(PSInput input) : SV_Target
{
    float3 n = normalize(input.Normal);
    float ndl = dot(n, -LightDirection) * 0.5 + 0.5;
    float3 ramp = RampTexture.Sample(ClampSampler, float2(ndl, 0.5)).rgb;
    float4 diffuse = DiffuseTexture.Sample(WrapSampler, input.UV) * BaseColor;
    float rim = pow(1.0 - saturate(n.z), 4.0) * RimStrength;
    return float4(diffuse.rgb * ramp + rim, diffuse.a);
}
