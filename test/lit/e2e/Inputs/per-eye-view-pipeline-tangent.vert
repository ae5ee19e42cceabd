#version 450
// A tangent-space vector from the camera position, handed to the fragment stage.
layout(set = 0, binding = 0) uniform Frame { mat4 viewProj; vec3 cameraPosition; } frame;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUV;
layout(location = 2) in vec3 inNormal;
layout(location = 3) in vec3 inTangent;
layout(location = 0) out vec2 outUV;
layout(location = 1) out vec3 outToReference;
void main() {
  outUV = inUV;
  mat3 toTangent = transpose(mat3(inTangent, cross(inNormal, inTangent), inNormal));
  outToReference = toTangent * (frame.cameraPosition - inPosition);
  gl_Position = frame.viewProj * vec4(inPosition, 1.0);
}
