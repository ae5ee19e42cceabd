#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec2 inGrid;
layout(location = 0) out vec2 outUv;

void main() {
  outUv = inGrid;
  float height = textureLod(heightMap, inGrid, 0.0).r;
  gl_Position = worldToClip(vec3(inGrid.x, height, inGrid.y));
}
