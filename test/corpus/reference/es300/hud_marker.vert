#version 300 es

invariant gl_Position;

uniform vec2 uMarkerNdc;
uniform vec2 uMarkerHalfSize;
uniform float uMarkerDepth;
uniform float uDepthZ;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec2 aCorner;
out mediump vec2 vTexCoord;
layout(location = 1) in vec2 aTexCoord;
out mediump float vFade;

void main()
{
    vec2 p = uMarkerNdc + (aCorner * uMarkerHalfSize);
    float d = max(uMarkerDepth, 0.100000001490116119384765625);
    vTexCoord = aTexCoord;
    vFade = clamp(d / 50.0, 0.300000011920928955078125, 1.0);
    vec2 _47 = p * d;
    float _51 = uDepthZ * d;
    float _53 = _47.x;
    float _54 = _47.y;
    vec4 _55 = vec4(_53, _54, _51, d);
    gl_Position = _55;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _85 = gl_Position.w - convergence;
        float _86 = eyeSign * separation;
        float _87 = _86 * _85;
        float _88 = gl_Position.x + _87;
        gl_Position.x = _88;
    }
}

