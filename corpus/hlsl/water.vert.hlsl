// stereoshift-expect: shift
// D3D11 water vertex shader: scrolling-normal water plane that also copies the clip position and screen UVs derived from it (halo case).

cbuffer WaterConstants : register(b0)
{
    float4x4 World;
    float4x4 ViewProj;
    float2   ScrollSpeed;
    float    Time;
    float    Padding;
};

struct VSInput
{
    float3 Position : POSITION;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float4 ClipPos  : TEXCOORD0;
    float2 ScreenUV : TEXCOORD1;
    float2 UV0      : TEXCOORD2;
    float2 UV1      : TEXCOORD3;
};

VSOutput main(VSInput input)
{
    VSOutput output;
    float4 world = mul(World, float4(input.Position, 1.0));
    output.Position = mul(ViewProj, world);
    output.ClipPos = output.Position;
    output.ScreenUV = output.Position.xy / output.Position.w * float2(0.5, -0.5) + 0.5;
    output.UV0 = input.UV + ScrollSpeed * Time;
    output.UV1 = input.UV * 1.7 - ScrollSpeed.yx * Time * 0.6;
    return output;
}
