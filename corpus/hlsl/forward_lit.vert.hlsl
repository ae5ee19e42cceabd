// stereoshift-expect: shift
// D3D11 forward-lit mesh vertex shader: row-vector mul(v, M) convention with a combined world-view-projection.

cbuffer PerObject : register(b0)
{
    row_major float4x4 WorldViewProj;
    row_major float4x4 WorldMatrix;
    float4 MaterialTint;
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
    float3 WorldNormal : TEXCOORD0;
    float2 UV : TEXCOORD1;
    float4 Tint : COLOR0;
};

VSOutput VSMain(VSInput input)
{
    VSOutput output;
    output.Position = mul(float4(input.Position, 1.0), WorldViewProj);
    output.WorldNormal = normalize(mul(input.Normal, (float3x3)WorldMatrix));
    output.UV = input.UV;
    output.Tint = MaterialTint;
    return output;
}
