#version 330

uniform mat4 model;
uniform vec3 viewPos;
uniform mat4 projection;
uniform mat4 view;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec3 aTangent;
out VS_OUT
{
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} vs_out;

layout(location = 2) in vec2 aTexCoords;

void main()
{
    vec3 worldPos = vec3((model * vec4(aPos, 1.0)).xyz);
    vec3 N = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aNormal);
    vec3 T = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aTangent);
    vec3 B = cross(N, T);
    mat3 TBN = transpose(mat3(vec3(T), vec3(B), vec3(N)));
    vs_out.TexCoords = aTexCoords;
    vs_out.TangentViewPos = TBN * (viewPos + (inverse(projection * view) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz);
    vs_out.TangentFragPos = TBN * worldPos;
    gl_Position = (projection * view) * vec4(worldPos, 1.0);
}

