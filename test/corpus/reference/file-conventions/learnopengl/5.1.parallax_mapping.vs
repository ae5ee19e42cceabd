#version 330

invariant gl_Position;

uniform mat4 model;
uniform vec3 lightPos;
uniform mat4 projection;
uniform mat4 view;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out VS_OUT
{
    vec3 FragPos;
    vec2 TexCoords;
    vec3 TangentLightPos;
    vec3 TangentFragPos;
} vs_out;

layout(location = 0) in vec3 aPos;
layout(location = 2) in vec2 aTexCoords;
layout(location = 3) in vec3 aTangent;
layout(location = 4) in vec3 aBitangent;
layout(location = 1) in vec3 aNormal;

void main()
{
    vs_out.FragPos = vec3((model * vec4(aPos, 1.0)).xyz);
    vs_out.TexCoords = aTexCoords;
    vec3 T = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aTangent);
    vec3 B = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aBitangent);
    vec3 N = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aNormal);
    mat3 TBN = transpose(mat3(vec3(T), vec3(B), vec3(N)));
    vs_out.TangentLightPos = TBN * lightPos;
    vs_out.TangentFragPos = TBN * vs_out.FragPos;
    mat4 _124 = projection * view;
    mat4 _126 = _124 * model;
    vec4 _131 = vec4(aPos, 1.0);
    vec4 _132 = _126 * _131;
    gl_Position = _132;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _162 = gl_Position.w - convergence;
        float _163 = eyeSign * separation;
        float _164 = _163 * _162;
        float _165 = gl_Position.x + _164;
        gl_Position.x = _165;
    }
}

