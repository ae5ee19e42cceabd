#version 300 es
// stereoshift-expect: fragment
// Particle fragment shader: soft round sprite modulated by the per-particle colour, premultiplied alpha.

precision mediump float;

in vec2 vUV;
in vec4 vColor;

uniform sampler2D uSprite;
uniform float uIntensity;

out vec4 fragColor;

void main()
{
    vec4 sprite = texture(uSprite, vUV);
    float radial = 1.0 - smoothstep(0.35, 0.5, length(vUV - 0.5));
    float alpha = sprite.a * vColor.a * radial;
    if (alpha <= 0.004)
        discard;
    fragColor = vec4(sprite.rgb * vColor.rgb * uIntensity * alpha, alpha);
}
