#version 330
// stereoshift-expect: fragment
// Shadow-map depth pass fragment shader with alpha-tested cutouts (foliage, fences).

in vec2 vTexCoord;

uniform sampler2D uAlphaMask;
uniform float uAlphaCutoff;

out vec4 fragColor;

void main()
{
    float alpha = texture(uAlphaMask, vTexCoord).a;
    if (alpha < uAlphaCutoff)
        discard;
    // Color writes are masked off by the pass; keep a defined output anyway.
    fragColor = vec4(gl_FragCoord.z);
}
