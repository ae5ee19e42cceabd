#version 450

layout(set = 0, binding = 0, std140) uniform Sky {
  mat4 rotationProj;  // projection * view without the translation
} sky;

layout(location = 0) in vec3 inDirection;
layout(location = 0) out vec3 outDirection;

void main() {
  outDirection = inDirection;
  gl_Position = (sky.rotationProj * vec4(inDirection, 1.0)).xyww;  // at the far plane
}
