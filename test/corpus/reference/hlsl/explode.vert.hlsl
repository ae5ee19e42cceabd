// stereoshift-expect: intermediate
// D3D11 mesh-explosion vertex shader: world-space pass-through feeding the geometry shader.

cbuffer ObjectConstants : register(b0)
{
    float4x4 World;
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 WorldPos : SV_Position;   // world space here, projected in the GS
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

VSOutput VSMain(VSInput input)
{
    VSOutput output;
    output.WorldPos = mul(World, float4(input.Position, 1.0));
    output.Normal = normalize(mul((float3x3)World, input.Normal));
    output.UV = input.UV;
    return output;
}
