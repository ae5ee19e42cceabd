#version 450
#include "scene_limits.h"

layout(location = 0) in vec3 vNormal;
layout(location = 1) in float vFog;
layout(location = 0) out vec4 outColor;

layout(set = 0, binding = 1) uniform Lights {
    vec4 direction[MAX_LIGHTS];
    vec4 color[MAX_LIGHTS];
} lights;

void main() {
    vec3 n = normalize(vNormal);
    vec3 lit = vec3(0.05);
    for (int i = 0; i < MAX_LIGHTS; ++i)
        lit += max(dot(n, -lights.direction[i].xyz), 0.0) * lights.color[i].rgb;
    outColor = vec4(mix(vec3(0.6, 0.7, 0.8), lit, vFog), 1.0);
}
