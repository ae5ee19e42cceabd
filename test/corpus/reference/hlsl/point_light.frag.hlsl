// stereoshift-expect: deferred-unproject
// D3D11 deferred point-light pixel shader: NDC from SV_Position, D3D [0,1] depth, world position via InvViewProj.

cbuffer LightConstants : register(b1)
{
    float4x4 InvViewProj;
    float3   LightPosition;
    float    LightRadius;
    float3   LightColor;
    float    Padding;
    float2   InvViewportSize;
    float2   Padding2;
};

Texture2D<float>  DepthBuffer : register(t0);
Texture2D<float4> AlbedoMetal : register(t1);
Texture2D<float4> NormalRough : register(t2);

struct PSInput
{
    float4 Position : SV_Position;
};

// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};
float4 stereoshift_unproject_InvViewProj(float4 stereoshift_q)
{
    return eyeSign != 0.0f ? stereoshift_q - float4(InvViewProj[0][0], InvViewProj[1][0], InvViewProj[2][0], InvViewProj[3][0]) * ((eyeSign * separation) * (1.0f - convergence * stereoshift_q.w)) : stereoshift_q;
}
// ---- end stereoshift ----
float4 PSMain(PSInput input) : SV_Target
{
    int3 pixel = int3(input.Position.xy, 0);
    float depth = DepthBuffer.Load(pixel);
    float2 uv = input.Position.xy * InvViewportSize;
    float2 ndc = float2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);

    float4 q = stereoshift_unproject_InvViewProj(mul(InvViewProj, float4(ndc, depth, 1.0)));
    float3 worldPos = q.xyz / q.w;

    float3 toLight = LightPosition - worldPos;
    float dist = length(toLight);
    if (dist > LightRadius)
        discard;

    float3 n = NormalRough.Load(pixel).xyz * 2.0 - 1.0;
    float3 albedo = AlbedoMetal.Load(pixel).rgb;
    float falloff = saturate(1.0 - dist * dist / (LightRadius * LightRadius));
    float ndl = saturate(dot(normalize(n), toLight / dist));
    return float4(albedo * LightColor * ndl * falloff * falloff, 0.0);
}
