#version 450
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vPos;
void main() {
  vPos = inPosition;
  gl_Position = vec4(inPosition.xy, 0.0, inPosition.z);
}
