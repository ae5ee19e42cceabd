// stereoshift-expect: shift
// packoffset-laid-out constants, explicit registers and a halo copy of the clip position in the output struct.
cbuffer Transforms : register(b2)
{
    float4x4 WorldViewProj : packoffset(c0);
    float4 Tint : packoffset(c4);
    float Scale : packoffset(c5.x);
};

Texture2D Detail : register(t3);
SamplerState Aniso : register(s1);

struct VSOut
{
    float4 Clip : SV_Position;
    float4 ClipCopy : TEXCOORD1;
    float2 UV : TEXCOORD0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b3)
{
    float eyeSign;
    float separation;
    float convergence;
};

VSOut stereoshift_shift_VSOut(VSOut stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Clip.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Clip.w))
    {
        precise float stereoshift_x = stereoshift_v.Clip.x + (eyeSign * separation) * (stereoshift_v.Clip.w - convergence);
        stereoshift_v.Clip.x = stereoshift_x;
    }
    if (eyeSign != 0.0f && abs(stereoshift_v.ClipCopy.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.ClipCopy.w))
    {
        precise float stereoshift_x1 = stereoshift_v.ClipCopy.x + (eyeSign * separation) * (stereoshift_v.ClipCopy.w - convergence);
        stereoshift_v.ClipCopy.x = stereoshift_x1;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VSOut main(float3 pos : POSITION, float2 uv : TEXCOORD0)
{
    VSOut o;
    o.Clip = mul(WorldViewProj, float4(pos * Scale, 1.0));
    o.ClipCopy = o.Clip;
    o.UV = uv;
    return stereoshift_shift_VSOut(o);
}

float4 mainPS(VSOut i) : SV_Target
{
    return Detail.Sample(Aniso, i.UV) * Tint;
}
