#version 450
layout(location = 0) out vec4 outColor;
void main() {
  outColor = vec4(0.2, 0.6, 0.1, 1.0);
}
