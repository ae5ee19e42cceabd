// Shared by the lit and terrain pipelines: an edit here reruns exactly those two conversions.
#ifndef COMMON_GLSL
#define COMMON_GLSL

layout(set = 0, binding = 0, std140) uniform Camera {
  mat4 viewProj;
  vec3 position;
} camera;

vec4 worldToClip(vec3 world) { return camera.viewProj * vec4(world, 1.0); }

#endif
