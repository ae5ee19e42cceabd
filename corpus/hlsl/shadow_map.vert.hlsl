// stereoshift-expect: shift
// D3D11 shadow-map vertex shader: light-space world-view-projection for a spot light (mono pass, decided per draw).

cbuffer ShadowConstants : register(b0)
{
    float4x4 LightWorldViewProj;
    float    NormalOffset;
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
};

VSOutput main(VSInput input)
{
    VSOutput output;
    // Normal-offset shadow bias applied in object space.
    float3 biased = input.Position + input.Normal * NormalOffset;
    output.Position = mul(LightWorldViewProj, float4(biased, 1.0));
    output.UV = input.UV;
    return output;
}
