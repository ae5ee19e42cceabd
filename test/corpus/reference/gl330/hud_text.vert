#version 330

invariant gl_Position;

uniform vec2 uTextOrigin;
uniform float uTextScale;
uniform mat4 uProjection;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec2 aPosition;
out vec2 vGlyphUV;
layout(location = 1) in vec2 aGlyphUV;
out vec4 vColor;
in vec4 aColor;

void main()
{
    vec2 pixel = uTextOrigin + (aPosition * uTextScale);
    vGlyphUV = aGlyphUV;
    vColor = aColor;
    vec4 _48 = vec4(pixel, 0.0, 1.0);
    vec4 _49 = uProjection * _48;
    gl_Position = _49;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _77 = gl_Position.w - convergence;
        float _78 = eyeSign * separation;
        float _79 = _78 * _77;
        float _80 = gl_Position.x + _79;
        gl_Position.x = _80;
    }
}

