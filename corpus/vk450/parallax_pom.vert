#version 450
// stereoshift-expect: per-eye-view
// Vulkan parallax-occlusion vertex shader: tangent-space view vector from camera.cameraPosition (shared include) minus world position.

#extension GL_GOOGLE_include_directive : require

#include "common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUV;

layout(location = 0) out vec2 outUV;
layout(location = 1) out vec3 outWorldPos;
layout(location = 2) out vec3 outViewTS;
layout(location = 3) out mat3 outWorldToTangent;   // occupies locations 3..5

void main()
{
    vec4 world = object.model * vec4(inPosition, 1.0);
    vec3 n = normalize(mat3(object.model) * inNormal);
    vec3 t = normalize(mat3(object.model) * inTangent.xyz);
    mat3 worldToTangent = buildWorldToTangent(n, t, inTangent.w);

    outUV = inUV;
    outWorldPos = world.xyz;
    outViewTS = worldToTangent * (camera.cameraPosition.xyz - world.xyz);
    outWorldToTangent = worldToTangent;
    gl_Position = camera.viewProj * world;
}
