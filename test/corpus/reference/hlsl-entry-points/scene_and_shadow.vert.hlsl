// stereoshift-expect: shift
// Main and shadow vertex shaders plus the PS of the main pass in one file: each VS is classified on its own.
cbuffer Frame : register(b0)
{
    float4x4 ViewProj;
    float4x4 LightViewProj;
};

cbuffer Object : register(b1)
{
    float4x4 World;
};

struct SceneOut
{
    float4 Pos : SV_Position;
    float4 LightPos : TEXCOORD0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};

SceneOut stereoshift_shift_SceneOut(SceneOut stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Pos.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Pos.w))
    {
        precise float stereoshift_x = stereoshift_v.Pos.x + (eyeSign * separation) * (stereoshift_v.Pos.w - convergence);
        stereoshift_v.Pos.x = stereoshift_x;
    }
    return stereoshift_v;
}

float4 stereoshift_shift_position(float4 stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.w))
    {
        precise float stereoshift_x = stereoshift_v.x + (eyeSign * separation) * (stereoshift_v.w - convergence);
        stereoshift_v.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

SceneOut VSMain(float3 pos : POSITION)
{
    SceneOut o;
    float4 world = mul(World, float4(pos, 1.0));
    o.Pos = mul(ViewProj, world);
    o.LightPos = mul(LightViewProj, world);
    return stereoshift_shift_SceneOut(o);
}

float4 VSShadow(float3 pos : POSITION) : SV_Position
{
    return stereoshift_shift_position(mul(LightViewProj, mul(World, float4(pos, 1.0))));
}

float4 PSMain(SceneOut i) : SV_Target
{
    float depth = i.LightPos.z / i.LightPos.w;
    return float4(depth.xxx, 1.0);
}
