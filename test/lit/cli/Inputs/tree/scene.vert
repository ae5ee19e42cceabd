#version 450
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vWorld;
void main() {
  vWorld = inPosition;
  gl_Position = vec4(inPosition, 2.0);
}
