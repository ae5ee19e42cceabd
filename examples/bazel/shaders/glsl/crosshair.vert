#version 450
// A screen-space overlay: already in clip space with w = 1, so it is left as it is.
layout(location = 0) in vec2 inPosition;
void main() { gl_Position = vec4(inPosition, 0.0, 1.0); }
