// stereoshift-expect: intermediate
// Stage-named HLSL point vertex shader: passes each particle's world-space centre and size on to the billboard geometry shader.

struct VSInput
{
[[vk::location(0)]] float4 PosSize : POSITION0;
[[vk::location(1)]] float4 Color : COLOR0;
};

struct VSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float4 Color : COLOR0;
[[vk::location(1)]] float Size : TEXCOORD0;
};

VSOutput main(VSInput input)
{
    VSOutput output = (VSOutput)0;
    output.Pos = float4(input.PosSize.xyz, 1.0);
    output.Color = input.Color;
    output.Size = input.PosSize.w;
    return output;
}
