// stereoshift-expect: shift
// Book-style vertex shader named `*_vs.hlsl`: a height-mapped terrain grid, entry point VSMain.
cbuffer TerrainConstants : register(b0)
{
    float4x4 WorldViewProj;
    float HeightScale;
    float3 Padding;
};
Texture2D HeightMap : register(t0);
SamplerState PointClamp : register(s0);

struct VertexOut
{
    float4 PosH : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b1)
{
    float eyeSign;
    float separation;
    float convergence;
};

VertexOut stereoshift_shift_VertexOut(VertexOut stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.PosH.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.PosH.w))
    {
        precise float stereoshift_x = stereoshift_v.PosH.x + (eyeSign * separation) * (stereoshift_v.PosH.w - convergence);
        stereoshift_v.PosH.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VertexOut VSMain(float3 posL : POSITION, float2 tex : TEXCOORD0)
{
    VertexOut vout;
    float height = HeightMap.SampleLevel(PointClamp, tex, 0).r * HeightScale;
    vout.PosH = mul(float4(posL.x, height, posL.z, 1.0f), WorldViewProj);
    vout.Tex = tex;
    return stereoshift_shift_VertexOut(vout);
}
