#version 330
// stereoshift-expect: shift
// HUD text vertex shader: glyph quads in pixels through an orthographic matrix (w is 1 only via the matrix).

layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec2 aGlyphUV;
in vec4 aColor;

uniform mat4 uProjection;
uniform vec2 uTextOrigin;
uniform float uTextScale;

out vec2 vGlyphUV;
out vec4 vColor;

void main_stereoshift_mono()
{
    vec2 pixel = uTextOrigin + aPosition * uTextScale;
    vGlyphUV = aGlyphUV;
    vColor = aColor;
    gl_Position = uProjection * vec4(pixel, 0.0, 1.0);
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
