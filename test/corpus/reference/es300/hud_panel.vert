#version 300 es
// stereoshift-expect: 2d
// HUD panel vertex shader: rectangle placed directly in NDC with a literal w of 1.0 (no matrix).

precision highp float;

layout(location = 0) in vec2 aUnitPos;   // unit quad in [0,1]

uniform vec4 uRectNdc;    // xy = min corner, zw = size, all in NDC
uniform vec4 uUVRect;     // atlas sub-rectangle

out mediump vec2 vUV;
out mediump vec2 vLocal;

void main()
{
    vec2 ndc = uRectNdc.xy + aUnitPos * uRectNdc.zw;
    vUV = uUVRect.xy + aUnitPos * uUVRect.zw;
    vLocal = aUnitPos;
    gl_Position = vec4(ndc, 0.0, 1.0);
}
