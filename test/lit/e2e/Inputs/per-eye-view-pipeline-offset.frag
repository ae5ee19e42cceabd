#version 450
// Steps the texture coordinates along the interpolated vector: it is a view vector.
layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inToReference;
layout(location = 0) out vec4 outColor;
void main() {
  vec3 v = normalize(inToReference);
  outColor = texture(heightMap, inUV + v.xy / v.z * 0.03);
}
