// stereoshift-expect: shift
// Stage-named HLSL skybox vertex shader: rotation-only view from the float4x4 cut to float3x3, cube-map direction out, position .xyww on the far plane.

struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
};

struct UBO
{
    float4x4 projection;
    float4x4 view;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct VSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float3 UVW : TEXCOORD0;
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
    if (eyeSign != 0.0f && abs(stereoshift_v.Pos.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Pos.w))
    {
        precise float stereoshift_x = stereoshift_v.Pos.x + (eyeSign * separation) * (stereoshift_v.Pos.w - convergence);
        stereoshift_v.Pos.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VSOutput main(VSInput input)
{
    VSOutput output = (VSOutput)0;
    output.UVW = input.Pos;
    float3 rotated = mul((float3x3)ubo.view, input.Pos);
    float4 clip = mul(ubo.projection, float4(rotated, 1.0));
    output.Pos = clip.xyww;
    return stereoshift_shift_VSOutput(output);
}
