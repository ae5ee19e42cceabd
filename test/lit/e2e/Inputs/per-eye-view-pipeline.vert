#version 450
// A world-space vector from a uniform whose name says nothing, handed to the fragment stage.
layout(set = 0, binding = 0) uniform Frame { mat4 viewProj; vec3 reference; } frame;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUV;
layout(location = 0) out vec2 outUV;
layout(location = 1) out vec3 outToReference;
void main() {
  outUV = inUV;
  outToReference = frame.reference - inPosition;
  gl_Position = frame.viewProj * vec4(inPosition, 1.0);
}
