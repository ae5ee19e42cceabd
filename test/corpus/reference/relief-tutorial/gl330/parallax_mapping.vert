#version 330

invariant gl_Position;

uniform mat4 model;
uniform vec3 lightPos;
uniform vec3 viewPos;
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
    vec3 TangentViewPos;
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
    mat3 normalMatrix = mat3(model[0].xyz, model[1].xyz, model[2].xyz);
    vec3 T = normalize(normalMatrix * aTangent);
    vec3 B = normalize(normalMatrix * aBitangent);
    vec3 N = normalize(normalMatrix * aNormal);
    mat3 TBN = transpose(mat3(vec3(T), vec3(B), vec3(N)));
    vs_out.TangentLightPos = TBN * lightPos;
    vs_out.TangentViewPos = TBN * (viewPos + (inverse(projection * view) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz);
    vs_out.TangentFragPos = TBN * vs_out.FragPos;
    mat4 _118 = projection * view;
    mat4 _120 = _118 * model;
    vec4 _125 = vec4(aPos, 1.0);
    vec4 _126 = _120 * _125;
    gl_Position = _126;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _156 = gl_Position.w - convergence;
        float _157 = eyeSign * separation;
        float _158 = _157 * _156;
        float _159 = gl_Position.x + _158;
        gl_Position.x = _159;
    }
}

