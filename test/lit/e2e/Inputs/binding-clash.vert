#version 450
layout(set = 0, binding = 1) uniform Object { mat4 model; } object;
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vWorld;
void main() {
  vWorld = (object.model * vec4(inPosition, 1.0)).xyz;
  gl_Position = vec4(vWorld, 2.0);
}
