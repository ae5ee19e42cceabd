#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(set = 0, binding = 1) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 vWorld[];
void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = camera.viewProj * vec4(vWorld[i], 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
