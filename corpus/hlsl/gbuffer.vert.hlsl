// stereoshift-expect: shift
// D3D11 G-buffer vertex shader: world-space normal/tangent frame and view depth for the geometry pass.

cbuffer ObjectConstants : register(b0)
{
    float4x4 World;
    float4x4 ViewProj;
    float4x4 View;
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float4 Tangent  : TANGENT;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position  : SV_Position;
    float3 Normal    : TEXCOORD0;
    float3 Tangent   : TEXCOORD1;
    float3 Bitangent : TEXCOORD2;
    float2 UV        : TEXCOORD3;
    float  ViewDepth : TEXCOORD4;
};

VSOutput VSMain(VSInput input)
{
    float4 world = mul(World, float4(input.Position, 1.0));
    VSOutput output;
    output.Position = mul(ViewProj, world);
    output.Normal = normalize(mul((float3x3)World, input.Normal));
    output.Tangent = normalize(mul((float3x3)World, input.Tangent.xyz));
    output.Bitangent = cross(output.Normal, output.Tangent) * input.Tangent.w;
    output.UV = input.UV;
    output.ViewDepth = mul(View, world).z;
    return output;
}
