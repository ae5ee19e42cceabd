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

void main()
{
    vec2 pixel = uTextOrigin + aPosition * uTextScale;
    vGlyphUV = aGlyphUV;
    vColor = aColor;
    gl_Position = uProjection * vec4(pixel, 0.0, 1.0);
}
