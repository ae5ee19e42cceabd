#version 330

invariant gl_Position;

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
out vec2 TexCoords;
layout(location = 2) in vec2 aTexCoords;
out vec3 TangentViewPos;
out vec3 TangentFragPos;

void main()
{
    vec3 worldPos = vec3((model * vec4(aPos, 1.0)).xyz);
    vec3 N = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aNormal);
    vec3 T = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * aTangent);
    T = normalize(T - (N * dot(T, N)));
    vec3 B = cross(N, T);
    mat3 TBN = transpose(mat3(vec3(T), vec3(B), vec3(N)));
    TexCoords = aTexCoords;
    TangentViewPos = TBN * (viewPos + (inverse(projection * view) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz);
    TangentFragPos = TBN * worldPos;
    mat4 _116 = projection * view;
    vec4 _121 = vec4(worldPos, 1.0);
    vec4 _122 = _116 * _121;
    gl_Position = _122;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _152 = gl_Position.w - convergence;
        float _153 = eyeSign * separation;
        float _154 = _153 * _152;
        float _155 = gl_Position.x + _154;
        gl_Position.x = _155;
    }
}

