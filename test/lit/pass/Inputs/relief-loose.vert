#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
layout (location = 3) in vec3 aTangent;
out vec2 TexCoords;
out vec3 TangentViewPos;
out vec3 TangentFragPos;
uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform vec3 viewPos;
void main()
{
    vec3 fragPos = vec3(model * vec4(aPos, 1.0));
    vec3 N = normalize(mat3(model) * aNormal);
    vec3 T = normalize(mat3(model) * aTangent);
    mat3 TBN = transpose(mat3(T, cross(N, T), N));
    TexCoords = aTexCoords;
    TangentViewPos = TBN * viewPos;
    TangentFragPos = TBN * fragPos;
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
