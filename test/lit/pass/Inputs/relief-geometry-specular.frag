#version 330 core
// A geometry stage's tangent-space varyings used for a highlight only: the view vector lights, it
// moves no texture coordinate.
out vec4 FragColor;
in GS_OUT {
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} fs_in;
uniform sampler2D diffuseMap;
uniform vec3 lightDirTS;
void main()
{
    vec3 viewDir = normalize(fs_in.TangentViewPos - fs_in.TangentFragPos);
    vec3 halfway = normalize(lightDirTS + viewDir);
    float spec = pow(max(halfway.z, 0.0), 32.0);
    FragColor = vec4(texture(diffuseMap, fs_in.TexCoords).rgb + vec3(spec), 1.0);
}
