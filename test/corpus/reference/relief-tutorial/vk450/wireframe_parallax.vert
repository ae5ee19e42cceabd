#version 450

layout(set = 0, binding = 0, std140) uniform UBO
{
    mat4 projection;
    mat4 view;
    mat4 model;
    vec4 cameraPos;
} ubo;

layout(set = 0, binding = 5, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) in vec3 inPos;
layout(location = 2) in vec3 inNormal;
layout(location = 3) in vec4 inTangent;
layout(location = 0) out vec2 outUV;
layout(location = 1) in vec2 inUV;
layout(location = 1) out vec3 outTangentViewPos;
layout(location = 2) out vec3 outTangentFragPos;

void main()
{
    vec3 worldPos = vec3((ubo.model * vec4(inPos, 1.0)).xyz);
    vec3 N = normalize(mat3(ubo.model[0].xyz, ubo.model[1].xyz, ubo.model[2].xyz) * inNormal);
    vec3 T = normalize(mat3(ubo.model[0].xyz, ubo.model[1].xyz, ubo.model[2].xyz) * inTangent.xyz);
    vec3 B = normalize(cross(N, T)) * inTangent.w;
    mat3 TBN = transpose(mat3(vec3(T), vec3(B), vec3(N)));
    outUV = inUV;
    outTangentViewPos = TBN * (ubo.cameraPos + vec4((inverse(ubo.projection * ubo.view) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0)).xyz;
    outTangentFragPos = TBN * worldPos;
    gl_Position = (ubo.projection * ubo.view) * vec4(worldPos, 1.0);
}

