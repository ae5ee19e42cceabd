#version 450
// Blinn-Phong: the camera position feeds only the specular half vector.
layout(set = 0, binding = 0) uniform Frame { vec3 cameraPosition; vec3 sunDirection; } frame;
layout(set = 0, binding = 1) uniform sampler2D albedo;
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 n = normalize(inNormal);
  vec3 v = normalize(frame.cameraPosition - inWorldPos);
  vec3 h = normalize(v - frame.sunDirection);
  float specular = pow(max(dot(n, h), 0.0), 32.0);
  outColor = texture(albedo, inUV) * max(dot(n, -frame.sunDirection), 0.0) + vec4(specular);
}
