// stereoshift-expect: compute
// D3D11 auto-exposure compute shader: reduces log-luminance of the HDR frame and adapts the exposure over time.

cbuffer ExposureConstants : register(b0)
{
    uint2 InputSize;
    float AdaptationRate;
    float DeltaTime;
    float MinLogLum;
    float MaxLogLum;
    float2 Padding;
};

Texture2D<float4>         HdrInput       : register(t0);
RWStructuredBuffer<float> AdaptedLum     : register(u0);

groupshared float PartialSums[256];

[numthreads(16, 16, 1)]
void main(uint3 groupThreadId : SV_GroupThreadID, uint groupIndex : SV_GroupIndex)
{
    float sum = 0.0;
    for (uint y = groupThreadId.y; y < InputSize.y; y += 16) {
        for (uint x = groupThreadId.x; x < InputSize.x; x += 16) {
            float3 c = HdrInput.Load(int3(x, y, 0)).rgb;
            float lum = dot(c, float3(0.2126, 0.7152, 0.0722));
            sum += clamp(log2(max(lum, 1e-5)), MinLogLum, MaxLogLum);
        }
    }
    PartialSums[groupIndex] = sum;
    GroupMemoryBarrierWithGroupSync();

    [unroll] for (uint stride = 128; stride > 0; stride >>= 1) {
        if (groupIndex < stride)
            PartialSums[groupIndex] += PartialSums[groupIndex + stride];
        GroupMemoryBarrierWithGroupSync();
    }

    if (groupIndex == 0) {
        float avgLum = exp2(PartialSums[0] / float(InputSize.x * InputSize.y));
        float previous = AdaptedLum[0];
        AdaptedLum[0] = previous + (avgLum - previous) * (1.0 - exp(-DeltaTime * AdaptationRate));
    }
}
