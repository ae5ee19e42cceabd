#version 450
// stereoshift-expect: per-eye-view
// Vulkan parallax-occlusion fragment shader: recomputes the per-pixel view vector from camera.cameraPosition and steps UVs through the height map.

#extension GL_GOOGLE_include_directive : require

#include "common.glsl"

layout(set = 1, binding = 0) uniform sampler2D heightMap;
layout(set = 1, binding = 1) uniform sampler2D albedoMap;

layout(set = 1, binding = 2) uniform PomParams {
    float heightScale;
    int minSteps;
    int maxSteps;
} pom;

layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inWorldPos;
layout(location = 2) in vec3 inViewTS;
layout(location = 3) in mat3 inWorldToTangent;

layout(location = 0) out vec4 outColor;

/* ---- stereoshift ---- */ vec4 stereoshift_eye_camera_cameraPosition(vec4 stereoshift_camera); /* ---- end stereoshift ---- */ void main()
{
    // Per-pixel view vector is more accurate than the interpolated one on large quads.
    vec3 viewTS = normalize(inWorldToTangent * (stereoshift_eye_camera_cameraPosition(camera.cameraPosition).xyz - inWorldPos));
    int steps = int(mix(float(pom.maxSteps), float(pom.minSteps), abs(viewTS.z)));
    vec2 stepUV = -viewTS.xy / max(viewTS.z, 0.05) * pom.heightScale / float(steps);
    float stepDepth = 1.0 / float(steps);

    vec2 uv = inUV;
    float rayDepth = 0.0;
    float surfaceDepth = 1.0 - texture(heightMap, uv).r;
    for (int i = 0; i < steps && rayDepth < surfaceDepth; ++i) {
        uv += stepUV;
        rayDepth += stepDepth;
        surfaceDepth = 1.0 - texture(heightMap, uv).r;
    }

    vec3 albedo = srgbToLinear(texture(albedoMap, uv).rgb);
    outColor = vec4(albedo, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_eye_camera_cameraPosition(vec4 stereoshift_camera)
{
    return stereoshift_camera + vec4((camera.invViewProj * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
}
// ---- end stereoshift ----
