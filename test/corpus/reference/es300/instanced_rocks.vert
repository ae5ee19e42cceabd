#version 300 es

invariant gl_Position;

uniform mediump vec3 uTintA;
uniform mediump vec3 uTintB;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 3) in mat4 aInstanceModel;
layout(location = 0) in vec3 aPosition;
out mediump vec3 vNormal;
layout(location = 1) in vec3 aNormal;
out mediump vec2 vTexCoord;
layout(location = 2) in vec2 aTexCoord;
out mediump vec3 vTint;

float hash(int n)
{
    return fract(sin(float(n) * 12.98980045318603515625) * 43758.546875);
}

void main()
{
    vec4 world = aInstanceModel * vec4(aPosition, 1.0);
    vNormal = normalize(mat3(aInstanceModel[0].xyz, aInstanceModel[1].xyz, aInstanceModel[2].xyz) * aNormal);
    vTexCoord = aTexCoord;
    int param = gl_InstanceID;
    vTint = mix(uTintA, uTintB, vec3(hash(param)));
    vec4 _82 = uViewProj * world;
    gl_Position = _82;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _111 = gl_Position.w - convergence;
        float _112 = eyeSign * separation;
        float _113 = _112 * _111;
        float _114 = gl_Position.x + _113;
        gl_Position.x = _114;
    }
}

