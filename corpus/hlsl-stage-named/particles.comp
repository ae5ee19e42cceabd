// stereoshift-expect: compute
// Stage-named HLSL compute shader: integrates particle positions in a [[vk::binding]] RWStructuredBuffer with gravity, wrapping at the floor.

struct Particle
{
    float4 PosSize;
    float4 Velocity;
};

[[vk::binding(0, 0)]] RWStructuredBuffer<Particle> particles : register(u0);

struct Params
{
    float deltaT;
    uint count;
};
[[vk::binding(1, 0)]] cbuffer params : register(b1) { Params params; }

[numthreads(256, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint index = id.x;
    if (index >= params.count)
        return;
    Particle p = particles[index];
    p.Velocity.y -= 9.81 * params.deltaT;
    p.PosSize.xyz += p.Velocity.xyz * params.deltaT;
    if (p.PosSize.y < 0.0)
    {
        p.PosSize.y += 10.0;
        p.Velocity.xyz = float3(0.0, 0.0, 0.0);
    }
    particles[index] = p;
}
