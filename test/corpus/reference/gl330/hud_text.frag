#version 330
// stereoshift-expect: fragment
// HUD text fragment shader: signed-distance-field glyphs with a soft outline.

in vec2 vGlyphUV;
in vec4 vColor;

uniform sampler2D uFontAtlas;
uniform float uSmoothing;
uniform vec4 uOutlineColor;

out vec4 fragColor;

void main()
{
    float dist = texture(uFontAtlas, vGlyphUV).r;
    float fill = smoothstep(0.5 - uSmoothing, 0.5 + uSmoothing, dist);
    float outline = smoothstep(0.35 - uSmoothing, 0.35 + uSmoothing, dist);
    vec4 color = mix(uOutlineColor, vColor, fill);
    color.a *= outline;
    if (color.a < 0.01)
        discard;
    fragColor = color;
}
