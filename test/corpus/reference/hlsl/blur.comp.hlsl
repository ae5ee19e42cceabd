// stereoshift-expect: compute
// D3D11 separable Gaussian blur compute shader: one horizontal pass through groupshared memory for bloom.

#define GROUP_SIZE 128
#define RADIUS 8

cbuffer BlurConstants : register(b0)
{
    float4 Weights[RADIUS + 1];   // x used
    uint2  TextureSize;
    uint2  Padding;
};

Texture2D<float4>   Source      : register(t0);
RWTexture2D<float4> Destination : register(u0);

groupshared float4 Cache[GROUP_SIZE + 2 * RADIUS];

[numthreads(GROUP_SIZE, 1, 1)]
void CSMain(uint3 dispatchId : SV_DispatchThreadID, uint3 groupThreadId : SV_GroupThreadID)
{
    int2 size = int2(TextureSize);
    int x = int(dispatchId.x);
    int y = min(int(dispatchId.y), size.y - 1);

    Cache[groupThreadId.x + RADIUS] = Source.Load(int3(min(x, size.x - 1), y, 0));
    if (groupThreadId.x < RADIUS) {
        Cache[groupThreadId.x] = Source.Load(int3(max(x - RADIUS, 0), y, 0));
        Cache[groupThreadId.x + GROUP_SIZE + RADIUS] = Source.Load(int3(min(x + GROUP_SIZE, size.x - 1), y, 0));
    }
    GroupMemoryBarrierWithGroupSync();

    if (x >= size.x || int(dispatchId.y) >= size.y)
        return;

    float4 sum = Cache[groupThreadId.x + RADIUS] * Weights[0].x;
    [unroll] for (int i = 1; i <= RADIUS; ++i) {
        sum += Cache[groupThreadId.x + RADIUS - i] * Weights[i].x;
        sum += Cache[groupThreadId.x + RADIUS + i] * Weights[i].x;
    }
    Destination[int2(x, y)] = sum;
}
