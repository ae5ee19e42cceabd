// stereoshift-expect: fragment
// Parallax-occlusion sample, pixel shader: gradient-sampled ray march along the tangent-space view vector.
cbuffer cbMaterial : register(b1)
{
    float gHeightScale;
    int gMinSamples;
    int gMaxSamples;
};

Texture2D gDiffuseMap : register(t0);
Texture2D gHeightMap : register(t1);
SamplerState gSampler : register(s0);

struct VertexOut
{
    float4 PosH : SV_POSITION;
    float2 Tex : TEXCOORD0;
    float3 EyePosT : TEXCOORD1;
    float3 PosT : TEXCOORD2;
};

float4 main(VertexOut pin) : SV_Target
{
    float3 toEye = normalize(pin.EyePosT - pin.PosT);
    float2 maxOffset = toEye.xy / toEye.z * gHeightScale;
    int samples = (int)lerp((float)gMaxSamples, (float)gMinSamples, saturate(toEye.z));
    float stepSize = 1.0f / (float)samples;
    float2 dx = ddx(pin.Tex);
    float2 dy = ddy(pin.Tex);
    float rayHeight = 1.0f;
    float2 offset = float2(0.0f, 0.0f);
    [loop]
    for (int i = 0; i < samples; ++i)
    {
        float h = gHeightMap.SampleGrad(gSampler, pin.Tex - offset, dx, dy).r;
        if (h >= rayHeight) break;
        rayHeight -= stepSize;
        offset += stepSize * maxOffset;
    }
    return gDiffuseMap.Sample(gSampler, pin.Tex - offset);
}
