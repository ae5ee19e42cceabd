#version 450
#include "camera.glsl"
#include "scene_limits.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out float vFog;

void main() {
    vec4 world = vec4(inPosition, 1.0);
    vNormal = inNormal;
    float distanceToEye = length(world.xyz - camera.eyePosition.xyz);
    vFog = exp(-FOG_DENSITY * distanceToEye);
    gl_Position = camera.viewProjection * world;
}
