#version 330 core
// stereoshift-expect: per-eye-view
// Steep-parallax floor tile, vertex stage: loose tangent-space varyings, tangent frame built from normal and tangent.
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
    vec3 worldPos = vec3(model * vec4(aPos, 1.0));
    vec3 N = normalize(mat3(model) * aNormal);
    vec3 T = normalize(mat3(model) * aTangent);
    T = normalize(T - dot(T, N) * N);
    vec3 B = cross(N, T);
    mat3 TBN = transpose(mat3(T, B, N));

    TexCoords = aTexCoords;
    TangentViewPos = TBN * viewPos;
    TangentFragPos = TBN * worldPos;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
