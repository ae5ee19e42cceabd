#version 300 es
// stereoshift-expect: fragment
// HUD panel fragment shader: textured fill with a solid border measured in panel space.

precision mediump float;

in vec2 vUV;
in vec2 vLocal;

uniform sampler2D uPanelAtlas;
uniform vec4 uFillColor;
uniform vec4 uBorderColor;
uniform float uBorderWidth;

out vec4 fragColor;

void main()
{
    vec2 edge = min(vLocal, 1.0 - vLocal);
    float border = 1.0 - step(uBorderWidth, min(edge.x, edge.y));
    vec4 fill = texture(uPanelAtlas, vUV) * uFillColor;
    fragColor = mix(fill, uBorderColor, border);
}
