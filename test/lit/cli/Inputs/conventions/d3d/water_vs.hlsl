cbuffer WaterConstants : register(b0)
{
    float4x4 WorldViewProj;
};
struct VSInput { float3 Position : POSITION; float2 Tex : TEXCOORD0; };
struct VSOutput { float4 Position : SV_POSITION; float2 Tex : TEXCOORD0; };
VSOutput main(VSInput input)
{
    VSOutput output;
    output.Position = mul(float4(input.Position, 1.0f), WorldViewProj);
    output.Tex = input.Tex;
    return output;
}
