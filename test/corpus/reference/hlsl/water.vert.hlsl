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

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};

VSOutput stereoshift_shift_VSOutput(VSOutput stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Position.w))
    {
        precise float stereoshift_x = stereoshift_v.Position.x + (eyeSign * separation) * (stereoshift_v.Position.w - convergence);
        stereoshift_v.Position.x = stereoshift_x;
    }
    if (eyeSign != 0.0f && abs(stereoshift_v.ClipPos.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.ClipPos.w))
    {
        precise float stereoshift_x1 = stereoshift_v.ClipPos.x + (eyeSign * separation) * (stereoshift_v.ClipPos.w - convergence);
        stereoshift_v.ClipPos.x = stereoshift_x1;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VSOutput main(VSInput input)
{
    VSOutput output;
    float4 world = mul(World, float4(input.Position, 1.0));
    output.Position = mul(ViewProj, world);
    output.ClipPos = output.Position;
    output.ScreenUV = output.Position.xy / output.Position.w * float2(0.5, -0.5) + 0.5;
    output.UV0 = input.UV + ScrollSpeed * Time;
    output.UV1 = input.UV * 1.7 - ScrollSpeed.yx * Time * 0.6;
    return stereoshift_shift_VSOutput(output);
}
