// stereoshift-expect: per-eye-view
// Parallax-occlusion sample, vertex shader: world and eye positions taken to tangent space and passed in the output struct.
cbuffer cbPerFrame : register(b0)
{
    float4x4 gWorld;
    float4x4 gViewProj;
    float3 gEyePosW;
    float gHeightScale;
};

struct VertexIn
{
    float3 PosL : POSITION;
    float3 NormalL : NORMAL;
    float2 Tex : TEXCOORD;
    float3 TangentL : TANGENT;
};

struct VertexOut
{
    float4 PosH : SV_POSITION;
    float2 Tex : TEXCOORD0;
    float3 EyePosT : TEXCOORD1;
    float3 PosT : TEXCOORD2;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
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
float4x4 stereoshift_inverse(float4x4 m)
{
    float s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1], s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
    float s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3], s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
    float s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3], s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
    float c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3], c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
    float c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2], c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
    float c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2], c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
    float d = 1.0f / (s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0);
    return float4x4(
        ( m[1][1] * c5 - m[1][2] * c4 + m[1][3] * c3) * d, (-m[0][1] * c5 + m[0][2] * c4 - m[0][3] * c3) * d,
        ( m[3][1] * s5 - m[3][2] * s4 + m[3][3] * s3) * d, (-m[2][1] * s5 + m[2][2] * s4 - m[2][3] * s3) * d,
        (-m[1][0] * c5 + m[1][2] * c2 - m[1][3] * c1) * d, ( m[0][0] * c5 - m[0][2] * c2 + m[0][3] * c1) * d,
        (-m[3][0] * s5 + m[3][2] * s2 - m[3][3] * s1) * d, ( m[2][0] * s5 - m[2][2] * s2 + m[2][3] * s1) * d,
        ( m[1][0] * c4 - m[1][1] * c2 + m[1][3] * c0) * d, (-m[0][0] * c4 + m[0][1] * c2 - m[0][3] * c0) * d,
        ( m[3][0] * s4 - m[3][1] * s2 + m[3][3] * s0) * d, (-m[2][0] * s4 + m[2][1] * s2 - m[2][3] * s0) * d,
        (-m[1][0] * c3 + m[1][1] * c1 - m[1][2] * c0) * d, ( m[0][0] * c3 - m[0][1] * c1 + m[0][2] * c0) * d,
        (-m[3][0] * s3 + m[3][1] * s1 - m[3][2] * s0) * d, ( m[2][0] * s3 - m[2][1] * s1 + m[2][2] * s0) * d);
}
float3 stereoshift_eye_gEyePosW(float3 stereoshift_camera)
{
    return stereoshift_camera + mul(stereoshift_inverse(gViewProj), float4((eyeSign * separation) * convergence, 0.0f, 0.0f, 0.0f)).xyz;
}
// ---- end stereoshift ----

VertexOut main(VertexIn vin)
{
    VertexOut vout;
    float4 posW = mul(gWorld, float4(vin.PosL, 1.0f));
    float3 N = normalize(mul((float3x3)gWorld, vin.NormalL));
    float3 T = normalize(mul((float3x3)gWorld, vin.TangentL));
    float3 B = cross(N, T);
    float3x3 toTangent = float3x3(T, B, N);
    vout.EyePosT = mul(toTangent, stereoshift_eye_gEyePosW(gEyePosW));
    vout.PosT = mul(toTangent, posW.xyz);
    vout.Tex = vin.Tex;
    vout.PosH = mul(gViewProj, posW);
    return stereoshift_shift_VertexOut(vout);
}
