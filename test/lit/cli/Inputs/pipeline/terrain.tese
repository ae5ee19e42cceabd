#version 450
layout(triangles, equal_spacing, ccw) in;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 tcPos[];
void main() {
  vec3 p = gl_TessCoord.x * tcPos[0] + gl_TessCoord.y * tcPos[1] + gl_TessCoord.z * tcPos[2];
  gl_Position = camera.viewProj * vec4(p, 1.0);
}
