#version 450
layout(push_constant) uniform Object { mat4 model; } object;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * object.model * vec4(inPosition, 1.0);
}
