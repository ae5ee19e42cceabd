#version 450
layout(location = 0) in vec3 vDirection;
layout(location = 0) out vec4 outColor;
layout(set = 0, binding = 0) uniform samplerCube skyTexture;

void main() { outColor = texture(skyTexture, normalize(vDirection)); }
