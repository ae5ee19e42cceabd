#version 300 es

invariant gl_Position;

uniform mat4 uModel;
uniform mediump vec3 uGroundColor;
uniform mediump vec3 uSkyColor;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 1) in vec3 aNormal;
out mediump vec3 vNormal;
out mediump vec3 vAmbient;
out mediump vec2 vTexCoord;
layout(location = 2) in vec2 aTexCoord;
layout(location = 0) in vec3 aPosition;

void main()
{
    vec3 n = normalize(mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz) * aNormal);
    vNormal = n;
    vAmbient = mix(uGroundColor, uSkyColor, vec3((n.y * 0.5) + 0.5));
    vTexCoord = aTexCoord;
    vec4 _67 = vec4(aPosition, 1.0);
    vec4 _68 = uModel * _67;
    vec4 _69 = uViewProj * _68;
    gl_Position = _69;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _100 = gl_Position.w - convergence;
        float _101 = eyeSign * separation;
        float _102 = _101 * _100;
        float _103 = gl_Position.x + _102;
        gl_Position.x = _103;
    }
}

