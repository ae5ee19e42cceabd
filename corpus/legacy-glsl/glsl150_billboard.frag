#version 150
// stereoshift-expect: fragment
// GLSL 1.50 billboard fragment shader: a round sprite cut out with discard.
in vec2 cornerUv;

out vec4 fragColor;

void main()
{
    vec2 d = cornerUv * 2.0 - 1.0;
    if (dot(d, d) > 1.0) discard;
    fragColor = vec4(1.0, 0.9, 0.6, 1.0);
}
