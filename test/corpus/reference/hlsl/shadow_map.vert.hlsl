// stereoshift-expect: shift
// D3D11 shadow-map vertex shader: light-space world-view-projection for a spot light (mono pass, decided per draw).

cbuffer ShadowConstants : register(b0)
{
    float4x4 LightWorldViewProj;
    float    NormalOffset;
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
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
    // Normal-offset shadow bias applied in object space.
    float3 biased = input.Position + input.Normal * NormalOffset;
    output.Position = mul(LightWorldViewProj, float4(biased, 1.0));
    output.UV = input.UV;
    return stereoshift_shift_VSOutput(output);
}
