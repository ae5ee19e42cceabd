#version 300 es

invariant gl_Position;

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

out mediump vec3 vNormal;
layout(location = 1) in vec3 aNormal;
out mediump vec3 vTangent;
layout(location = 2) in vec4 aTangent;
out mediump vec3 vBitangent;
out mediump vec2 vTexCoord;
layout(location = 3) in vec2 aTexCoord;
layout(location = 0) in vec3 aPosition;

void main()
{
    mat3 m = mat3(uModel[0].xyz, uModel[1].xyz, uModel[2].xyz);
    vNormal = normalize(m * aNormal);
    vTangent = normalize(m * aTangent.xyz);
    vBitangent = cross(vNormal, vTangent) * aTangent.w;
    vTexCoord = aTexCoord;
    mat4 _63 = uViewProj * uModel;
    vec4 _70 = vec4(aPosition, 1.0);
    vec4 _71 = _63 * _70;
    gl_Position = _71;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _102 = gl_Position.w - convergence;
        float _103 = eyeSign * separation;
        float _104 = _103 * _102;
        float _105 = gl_Position.x + _104;
        gl_Position.x = _105;
    }
}

