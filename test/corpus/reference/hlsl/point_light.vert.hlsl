// stereoshift-expect: shift
// D3D11 deferred point-light volume vertex shader: scales a unit sphere to the light radius and projects it.

cbuffer LightVolumeConstants : register(b0)
{
    float4x4 ViewProj;
    float3   LightPosition;
    float    LightRadius;
};

struct VSInput
{
    float3 Position : POSITION;   // unit icosphere
};

struct VSOutput
{
    float4 Position : SV_Position;
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
    // Inflate slightly so the low-poly sphere fully covers the true radius.
    float3 world = LightPosition + input.Position * LightRadius * 1.08;
    VSOutput output;
    output.Position = mul(ViewProj, float4(world, 1.0));
    return stereoshift_shift_VSOutput(output);
}
