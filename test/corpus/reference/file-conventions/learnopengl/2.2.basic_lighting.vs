#version 330

invariant gl_Position;

uniform mat4 model;
uniform mat4 projection;
uniform mat4 view;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out vec3 FragPos;
layout(location = 0) in vec3 aPos;
out vec3 Normal;
layout(location = 1) in vec3 aNormal;

void main()
{
    FragPos = vec3((model * vec4(aPos, 1.0)).xyz);
    mat4 _31 = transpose(inverse(model));
    Normal = mat3(_31[0].xyz, _31[1].xyz, _31[2].xyz) * aNormal;
    mat4 _55 = projection * view;
    vec4 _60 = vec4(FragPos, 1.0);
    vec4 _61 = _55 * _60;
    gl_Position = _61;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _92 = gl_Position.w - convergence;
        float _93 = eyeSign * separation;
        float _94 = _93 * _92;
        float _95 = gl_Position.x + _94;
        gl_Position.x = _95;
    }
}

