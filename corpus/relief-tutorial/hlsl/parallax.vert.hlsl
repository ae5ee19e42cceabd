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

VertexOut main(VertexIn vin)
{
    VertexOut vout;
    float4 posW = mul(gWorld, float4(vin.PosL, 1.0f));
    float3 N = normalize(mul((float3x3)gWorld, vin.NormalL));
    float3 T = normalize(mul((float3x3)gWorld, vin.TangentL));
    float3 B = cross(N, T);
    float3x3 toTangent = float3x3(T, B, N);
    vout.EyePosT = mul(toTangent, gEyePosW);
    vout.PosT = mul(toTangent, posW.xyz);
    vout.Tex = vin.Tex;
    vout.PosH = mul(gViewProj, posW);
    return vout;
}
