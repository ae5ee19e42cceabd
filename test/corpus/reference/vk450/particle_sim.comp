#version 450
// stereoshift-expect: compute
// Particle simulation compute shader: integrates velocity with gravity and drag, respawns expired particles.

layout(local_size_x = 256) in;

struct Particle {
    vec4 positionSize;   // xyz position, w size
    vec4 velocityAge;    // xyz velocity, w age in seconds
    vec4 color;
};

layout(std430, set = 0, binding = 0) buffer ParticleBuffer {
    Particle particles[];
};

layout(set = 0, binding = 1) uniform SimParams {
    vec4 gravity;        // xyz acceleration
    vec4 emitterPos;     // xyz position, w spread
    float deltaTime;
    float drag;
    float maxAge;
    uint particleCount;
} sim;

float rand(uint seed)
{
    seed = seed * 747796405u + 2891336453u;
    uint word = ((seed >> ((seed >> 28u) + 4u)) ^ seed) * 277803737u;
    return float((word >> 22u) ^ word) / 4294967295.0;
}

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= sim.particleCount)
        return;

    Particle p = particles[i];
    p.velocityAge.xyz += sim.gravity.xyz * sim.deltaTime;
    p.velocityAge.xyz *= 1.0 / (1.0 + sim.drag * sim.deltaTime);
    p.positionSize.xyz += p.velocityAge.xyz * sim.deltaTime;
    p.velocityAge.w += sim.deltaTime;

    if (p.velocityAge.w > sim.maxAge) {
        vec3 jitter = vec3(rand(i * 3u), rand(i * 3u + 1u), rand(i * 3u + 2u)) - 0.5;
        p.positionSize.xyz = sim.emitterPos.xyz + jitter * sim.emitterPos.w;
        p.velocityAge = vec4(jitter.x, 4.0 + jitter.y, jitter.z, 0.0);
    }
    particles[i] = p;
}
