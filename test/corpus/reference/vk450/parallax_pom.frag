#version 450

layout(set = 0, binding = 0, std140) uniform CameraBlock
{
    mat4 view;
    mat4 proj;
    mat4 viewProj;
    mat4 invViewProj;
    vec4 cameraPosition;
    vec4 viewportSize;
} camera;

layout(set = 1, binding = 2, std140) uniform PomParams
{
    float heightScale;
    int minSteps;
    int maxSteps;
} pom;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(push_constant, std430) uniform ObjectPush
{
    mat4 model;
    uint materialIndex;
} object;

layout(set = 1, binding = 0) uniform sampler2D heightMap;
layout(set = 1, binding = 1) uniform sampler2D albedoMap;

layout(location = 3) in mat3 inWorldToTangent;
layout(location = 1) in vec3 inWorldPos;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
layout(location = 2) in vec3 inViewTS;

vec3 srgbToLinear(vec3 c)
{
    return pow(c, vec3(2.2000000476837158203125));
}

void main()
{
    vec3 viewTS = normalize(inWorldToTangent * ((camera.cameraPosition + vec4((camera.invViewProj * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0)).xyz - inWorldPos));
    int steps = int(mix(float(pom.maxSteps), float(pom.minSteps), abs(viewTS.z)));
    vec2 stepUV = (((-viewTS.xy) / vec2(max(viewTS.z, 0.0500000007450580596923828125))) * pom.heightScale) / vec2(float(steps));
    float stepDepth = 1.0 / float(steps);
    vec2 uv = inUV;
    float rayDepth = 0.0;
    float surfaceDepth = 1.0 - texture(heightMap, uv).x;
    for (int i = 0; (i < steps) && (rayDepth < surfaceDepth); i++)
    {
        uv += stepUV;
        rayDepth += stepDepth;
        surfaceDepth = 1.0 - texture(heightMap, uv).x;
    }
    vec3 param = texture(albedoMap, uv).xyz;
    vec3 albedo = srgbToLinear(param);
    outColor = vec4(albedo, 1.0);
}

