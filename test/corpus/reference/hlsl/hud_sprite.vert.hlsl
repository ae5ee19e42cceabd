// stereoshift-expect: shift
// D3D11 HUD sprite vertex shader: pixel-space sprites through an orthographic projection matrix (w = 1 only via the matrix).

cbuffer HudConstants : register(b0)
{
    float4x4 OrthoProjection;
    float2   ScreenOffset;
    float    UiScale;
    float    Padding;
};

struct VSInput
{
    float2 Position : POSITION;    // pixels
    float2 UV       : TEXCOORD0;
    float4 Color    : COLOR0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
    float4 Color    : COLOR0;
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
    return stereoshift_v;
}
// ---- end stereoshift ----

VSOutput main(VSInput input)
{
    VSOutput output;
    float2 pixel = input.Position * UiScale + ScreenOffset;
    output.Position = mul(OrthoProjection, float4(pixel, 0.0, 1.0));
    output.UV = input.UV;
    output.Color = input.Color;
    return stereoshift_shift_VSOutput(output);
}
