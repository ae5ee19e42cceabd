#version 300 es

invariant gl_Position;

uniform vec3 uCameraRight;
uniform vec3 uCameraUp;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 3) in float aRotation;
layout(location = 0) in vec2 aCorner;
layout(location = 1) in vec4 aCenterSize;
out mediump vec2 vUV;
out mediump vec4 vColor;
layout(location = 2) in vec4 aColor;

void main()
{
    float s = sin(aRotation);
    float c = cos(aRotation);
    vec2 corner = vec2((c * aCorner.x) - (s * aCorner.y), (s * aCorner.x) + (c * aCorner.y));
    vec3 world = (aCenterSize.xyz + ((uCameraRight * corner.x) * aCenterSize.w)) + ((uCameraUp * corner.y) * aCenterSize.w);
    vUV = aCorner + vec2(0.5);
    vColor = aColor;
    vec4 _95 = vec4(world, 1.0);
    vec4 _96 = uViewProj * _95;
    gl_Position = _96;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _126 = gl_Position.w - convergence;
        float _127 = eyeSign * separation;
        float _128 = _127 * _126;
        float _129 = gl_Position.x + _128;
        gl_Position.x = _129;
    }
}

