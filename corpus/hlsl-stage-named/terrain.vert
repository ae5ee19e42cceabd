// stereoshift-expect: intermediate
// Stage-named HLSL terrain patch vertex shader: passes grid control points and their UVs on to the hull shader.

struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
[[vk::location(1)]] float2 UV : TEXCOORD0;
};

struct VSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
};

VSOutput main(VSInput input)
{
    VSOutput output = (VSOutput)0;
    output.Pos = float4(input.Pos, 1.0);
    output.UV = input.UV;
    return output;
}
