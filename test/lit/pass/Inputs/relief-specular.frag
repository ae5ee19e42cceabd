#version 330 core
in vec2 TexCoords;
in vec3 TangentViewPos;
in vec3 TangentFragPos;
out vec4 FragColor;
uniform sampler2D diffuseMap;
void main()
{
    vec3 viewDir = normalize(TangentViewPos - TangentFragPos);
    float spec = pow(max(viewDir.z, 0.0), 16.0);
    FragColor = texture(diffuseMap, TexCoords) + vec4(spec);
}
