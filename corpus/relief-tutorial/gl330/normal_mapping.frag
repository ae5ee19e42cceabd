#version 330 core
// stereoshift-expect: fragment
// Normal-mapped wall, fragment stage: Blinn-Phong in tangent space; the view direction only feeds the highlight.
out vec4 FragColor;

in VS_OUT {
    vec2 TexCoords;
    vec3 TangentLightPos;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} fs_in;

uniform sampler2D diffuseMap;
uniform sampler2D normalMap;

void main()
{
    vec3 normal = normalize(texture(normalMap, fs_in.TexCoords).rgb * 2.0 - 1.0);
    vec3 color = texture(diffuseMap, fs_in.TexCoords).rgb;
    vec3 lightDir = normalize(fs_in.TangentLightPos - fs_in.TangentFragPos);
    vec3 viewDir = normalize(fs_in.TangentViewPos - fs_in.TangentFragPos);
    float diff = max(dot(lightDir, normal), 0.0);
    float spec = pow(max(dot(normal, normalize(lightDir + viewDir)), 0.0), 32.0);
    FragColor = vec4(0.1 * color + diff * color + vec3(0.2) * spec, 1.0);
}
