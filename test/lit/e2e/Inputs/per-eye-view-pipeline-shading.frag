#version 450
// Only shades with the interpolated vector.
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inToReference;
layout(location = 0) out vec4 outColor;
void main() {
  outColor = vec4(normalize(inToReference) * 0.5 + 0.5, 1.0);
}
