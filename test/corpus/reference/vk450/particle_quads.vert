#version 450
// stereoshift-expect: intermediate
// Point-sprite particle vertex shader: passes world-space centres to the geometry shader for billboard expansion.

layout(location = 0) in vec4 inCenterSize;   // xyz world centre, w size
layout(location = 1) in vec4 inColor;
layout(location = 2) in float inAge;

layout(location = 0) out vec4 outColor;
layout(location = 1) out float outSize;

layout(set = 0, binding = 1) uniform ParticleParams {
    float maxAge;
    float growth;
} params;

void main()
{
    float t = clamp(inAge / params.maxAge, 0.0, 1.0);
    outColor = vec4(inColor.rgb, inColor.a * (1.0 - t));
    outSize = inCenterSize.w * (1.0 + params.growth * t);
    gl_Position = vec4(inCenterSize.xyz, 1.0);
}
