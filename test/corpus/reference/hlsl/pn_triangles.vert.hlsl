// stereoshift-expect: intermediate
// D3D11 PN-triangles vertex shader: world-space control points and normals for the hull shader.

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
    float3 WorldPos : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

VSOutput VSMain(VSInput input)
{
    VSOutput output;
    output.WorldPos = mul(World, float4(input.Position, 1.0)).xyz;
    output.Normal = normalize(mul((float3x3)World, input.Normal));
    output.UV = input.UV;
    return output;
}
