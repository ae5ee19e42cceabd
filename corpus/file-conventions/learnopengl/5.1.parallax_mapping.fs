#version 330 core
// stereoshift-expect: fragment
// LearnOpenGL-style fragment shader (`x.y.name.fs`): diffuse lighting in tangent space from a normal map.
out vec4 FragColor;

in VS_OUT {
    vec3 FragPos;
    vec2 TexCoords;
    vec3 TangentLightPos;
    vec3 TangentFragPos;
} fs_in;

uniform sampler2D diffuseMap;
uniform sampler2D normalMap;

void main()
{
    vec3 normal = normalize(texture(normalMap, fs_in.TexCoords).rgb * 2.0 - 1.0);
    vec3 color = texture(diffuseMap, fs_in.TexCoords).rgb;
    vec3 lightDir = normalize(fs_in.TangentLightPos - fs_in.TangentFragPos);
    float diff = max(dot(lightDir, normal), 0.0);
    FragColor = vec4((0.1 + diff) * color, 1.0);
}
