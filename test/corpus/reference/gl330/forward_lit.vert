#version 330

invariant gl_Position;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec3 aPosition;
out vec3 vWorldPos;
out vec3 vNormal;
in vec3 aNormal;
out vec2 vTexCoord;
in vec2 aTexCoord;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = normalize(uNormalMatrix * aNormal);
    vTexCoord = aTexCoord;
    vec4 _54 = uViewProj * world;
    gl_Position = _54;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _85 = gl_Position.w - convergence;
        float _86 = eyeSign * separation;
        float _87 = _86 * _85;
        float _88 = gl_Position.x + _87;
        gl_Position.x = _88;
    }
}

