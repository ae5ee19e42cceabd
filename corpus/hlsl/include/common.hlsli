// Shared declarations for the HLSL corpus (included, not a shader by itself).
#ifndef CORPUS_COMMON_HLSLI
#define CORPUS_COMMON_HLSLI

cbuffer FrameConstants : register(b0)
{
    float4x4 ViewProj;
    float4x4 InvViewProj;
    float3   CameraPosition;
    float    Time;
    float4   ViewportSize;   // xy = pixels, zw = 1 / pixels
};

cbuffer ObjectConstants : register(b1)
{
    float4x4 World;
    float4x4 WorldInvTranspose;
};

float3x3 WorldToTangentBasis(float3 n, float3 t, float handedness)
{
    float3 b = cross(n, t) * handedness;
    return float3x3(t, b, n);   // rows: multiplying mul(M, v) projects v on T, B, N
}

float3 DecodeNormal(float3 encoded)
{
    return normalize(encoded * 2.0 - 1.0);
}

#endif
