// stereoshift-expect: shift
// D3D11 skybox vertex shader: camera-centred cube, output position .xyww so the sky sits on the far plane.

cbuffer SkyConstants : register(b0)
{
    float4x4 ViewRotationProj;   // projection * view with the translation removed
    float4   SkyTint;
};

struct VSInput
{
    float3 Position : POSITION;
};

struct VSOutput
{
    float4 Position  : SV_Position;
    float3 Direction : TEXCOORD0;
    float4 Tint      : COLOR0;
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

VSOutput VSMain(VSInput input)
{
    VSOutput output;
    float4 pos = mul(ViewRotationProj, float4(input.Position, 1.0));
    output.Position = pos.xyww;
    output.Direction = input.Position;
    output.Tint = SkyTint;
    return stereoshift_shift_VSOutput(output);
}
