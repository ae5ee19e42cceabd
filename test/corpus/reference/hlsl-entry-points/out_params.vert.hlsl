// stereoshift-expect: shift
// Vertex outputs as out parameters (no struct), an early return for culled instances, and the PS beside it.
cbuffer PerFrame : register(b0)
{
    float4x4 gViewProj;
};

cbuffer PerInstance : register(b1)
{
    float4x4 gWorld;
    float gVisible;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};

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

void VSMain(in float3 iPos : POSITION, in float2 iUV : TEXCOORD0,
            out float4 oPos : SV_Position, out float2 oUV : TEXCOORD0)
{
    oUV = iUV;
    oPos = mul(gViewProj, mul(gWorld, float4(iPos, 1.0)));
    if (gVisible == 0.0)
    {
        oPos = float4(0.0, 0.0, -2.0, 1.0);
        { oPos = stereoshift_shift_position(oPos); return; }
    }
    oPos = stereoshift_shift_position(oPos);
}

float4 PSMain(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    return float4(uv, 0.0, 1.0);
}
