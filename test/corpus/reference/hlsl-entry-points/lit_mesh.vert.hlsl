// stereoshift-expect: shift
// Sample-framework style mainVS/mainPS pair in one file: a lit, textured mesh.
cbuffer cbPerObject : register(b0)
{
    float4x4 g_mWorldViewProjection;
    float4x4 g_mWorld;
};

cbuffer cbPerFrame : register(b1)
{
    float3 g_vLightDir;
    float g_fAmbient;
};

Texture2D g_txDiffuse : register(t0);
SamplerState g_samLinear : register(s0);

struct VS_INPUT
{
    float4 vPosition : POSITION;
    float3 vNormal : NORMAL;
    float2 vTexcoord : TEXCOORD0;
};

struct VS_OUTPUT
{
    float3 vNormal : NORMAL;
    float2 vTexcoord : TEXCOORD0;
    float4 vPosition : SV_POSITION;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};

VS_OUTPUT stereoshift_shift_VS_OUTPUT(VS_OUTPUT stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.vPosition.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.vPosition.w))
    {
        precise float stereoshift_x = stereoshift_v.vPosition.x + (eyeSign * separation) * (stereoshift_v.vPosition.w - convergence);
        stereoshift_v.vPosition.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VS_OUTPUT mainVS(VS_INPUT Input)
{
    VS_OUTPUT Output;
    Output.vPosition = mul(Input.vPosition, g_mWorldViewProjection);
    Output.vNormal = mul(Input.vNormal, (float3x3)g_mWorld);
    Output.vTexcoord = Input.vTexcoord;
    return stereoshift_shift_VS_OUTPUT(Output);
}

float4 mainPS(VS_OUTPUT Input) : SV_TARGET
{
    float4 vDiffuse = g_txDiffuse.Sample(g_samLinear, Input.vTexcoord);
    float fLighting = saturate(dot(g_vLightDir, normalize(Input.vNormal)));
    fLighting = max(fLighting, g_fAmbient);
    return vDiffuse * fLighting;
}
