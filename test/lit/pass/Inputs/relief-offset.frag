#version 330 core
in vec2 TexCoords;
in vec3 TangentViewPos;
in vec3 TangentFragPos;
out vec4 FragColor;
uniform sampler2D depthMap;
uniform sampler2D diffuseMap;
uniform float heightScale;
vec2 ParallaxMapping(vec2 texCoords, vec3 viewDir)
{
    float height = texture(depthMap, texCoords).r;
    return texCoords - viewDir.xy / viewDir.z * (height * heightScale);
}
void main()
{
    vec3 viewDir = normalize(TangentViewPos - TangentFragPos);
    FragColor = texture(diffuseMap, ParallaxMapping(TexCoords, viewDir));
}
