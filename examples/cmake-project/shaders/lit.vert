#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"

#ifndef NORMAL_SCALE
#define NORMAL_SCALE 1.0
#endif

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outToCamera;

void main() {
  outNormal = inNormal * NORMAL_SCALE;
  outToCamera = camera.position - inPosition;
  gl_Position = worldToClip(inPosition);
}
