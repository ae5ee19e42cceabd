// stereoshift-expect: per-eye-view
// D3D11 parallax-occlusion vertex shader: tangent-space view vector from CameraPosition (shared include) minus the world position.

#include "include/common.hlsli"

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float4 Tangent  : TANGENT;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
    float3 ViewTS   : TEXCOORD1;
    float3 NormalWS : TEXCOORD2;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b3)
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
float3 stereoshift_eye_CameraPosition(float3 stereoshift_camera)
{
    return stereoshift_camera + mul(InvViewProj, float4((eyeSign * separation) * convergence, 0.0f, 0.0f, 0.0f)).xyz;
}
// ---- end stereoshift ----

VSOutput main(VSInput input)
{
    float4 world = mul(World, float4(input.Position, 1.0));
    float3 n = normalize(mul((float3x3)WorldInvTranspose, input.Normal));
    float3 t = normalize(mul((float3x3)World, input.Tangent.xyz));
    float3x3 toTangent = WorldToTangentBasis(n, t, input.Tangent.w);

    VSOutput output;
    output.Position = mul(ViewProj, world);
    output.UV = input.UV;
    output.ViewTS = mul(toTangent, stereoshift_eye_CameraPosition(CameraPosition) - world.xyz);
    output.NormalWS = n;
    return stereoshift_shift_VSOutput(output);
}
