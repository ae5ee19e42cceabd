// Shared declarations for the vk450 corpus (included, not a shader by itself).
#ifndef CORPUS_COMMON_GLSL
#define CORPUS_COMMON_GLSL

// Per-view camera data, bound at set 0 / binding 0 in every pass that includes this file.
layout(set = 0, binding = 0) uniform CameraBlock {
    mat4 view;
    mat4 proj;
    mat4 viewProj;
    mat4 invViewProj;
    vec4 cameraPosition;   // xyz = world-space eye position, w unused
    vec4 viewportSize;     // xy = size in pixels, zw = 1 / size
} camera;

// Per-draw object transform pushed with vkCmdPushConstants.
layout(push_constant) uniform ObjectPush {
    mat4 model;
    uint materialIndex;
} object;

mat3 buildWorldToTangent(vec3 n, vec3 t, float handedness)
{
    vec3 b = cross(n, t) * handedness;
    return transpose(mat3(t, b, n));
}

vec3 srgbToLinear(vec3 c)
{
    return pow(c, vec3(2.2));
}

#endif
