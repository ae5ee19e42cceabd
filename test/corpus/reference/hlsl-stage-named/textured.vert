// stereoshift-expect: shift
// Vulkan-sample style HLSL vertex shader in a stage-only .vert file: [[vk::location]] inputs, a UBO struct in a cbuffer at [[vk::binding(0, 0)]], column-vector mul(M, v).

struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
[[vk::location(1)]] float3 Normal : NORMAL0;
[[vk::location(2)]] float2 UV : TEXCOORD0;
};

struct UBO
{
    float4x4 projection;
    float4x4 view;
    float4x4 model;
    float4 lightPos;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct VSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
[[vk::location(1)]] float3 Normal : NORMAL0;
[[vk::location(2)]] float3 LightVec : TEXCOORD1;
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
    float4 worldPos = mul(ubo.model, float4(input.Pos, 1.0));
    output.UV = input.UV;
    output.Normal = mul((float3x3)ubo.model, input.Normal);
    output.LightVec = ubo.lightPos.xyz - worldPos.xyz;
    output.Pos = mul(ubo.projection, mul(ubo.view, worldPos));
    return stereoshift_shift_VSOutput(output);
}
