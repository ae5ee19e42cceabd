#version 300 es
// stereoshift-expect: fragment
// HUD objective-marker fragment shader: icon atlas lookup with distance fade and pulse.

precision mediump float;

in vec2 vTexCoord;
in float vFade;

uniform sampler2D uIconAtlas;
uniform vec4 uIconColor;
uniform float uTime;

out vec4 fragColor;

void main()
{
    vec4 icon = texture(uIconAtlas, vTexCoord);
    float pulse = 0.85 + 0.15 * sin(uTime * 6.0);
    vec4 color = icon * uIconColor;
    color.a *= vFade * pulse;
    if (color.a < 0.02)
        discard;
    fragColor = color;
}
