// D3D11-style HLSL with per-class registers in two register spaces: a terrain vertex shader that
// fetches its height from a texture (t0 + s0) beside its constants (b0), per-instance world
// matrices in a StructuredBuffer (t1) and the camera in space1 (b0, space1). b0, t0 and s0 are
// three separate D3D namespaces: verify must bind them apart.
cbuffer cbTerrain : register(b0)
{
    float gHeightScale;
    float2 gTexelSize;
    float gPad;
};

cbuffer cbCamera : register(b0, space1)
{
    float4x4 gViewProj;
    float3 gEyePosW;
};

Texture2D gHeightMap : register(t0);
SamplerState gHeightSampler : register(s0);
StructuredBuffer<float4x4> gInstanceWorld : register(t1);

struct VSIn
{
    float3 PosL : POSITION;
    float2 Tex : TEXCOORD0;
    uint InstanceId : SV_InstanceID;
};

struct VSOut
{
    float4 PosH : SV_POSITION;
    float2 Tex : TEXCOORD0;
    float3 ToEye : TEXCOORD1;
};

VSOut main(VSIn vin)
{
    VSOut vout;
    float height = gHeightMap.SampleLevel(gHeightSampler, vin.Tex, 0).r * gHeightScale;
    float4 posW = mul(gInstanceWorld[vin.InstanceId], float4(vin.PosL + float3(0.0f, height, 0.0f), 1.0f));
    vout.PosH = mul(gViewProj, posW);
    vout.Tex = vin.Tex + gTexelSize * 0.5f;
    vout.ToEye = gEyePosW - posW.xyz;
    return vout;
}
