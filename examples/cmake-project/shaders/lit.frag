#version 450

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inToCamera;
layout(location = 0) out vec4 outColor;

void main() {
  float facing = max(dot(normalize(inNormal), normalize(inToCamera)), 0.0);
  outColor = vec4(vec3(0.1 + 0.9 * facing), 1.0);
}
