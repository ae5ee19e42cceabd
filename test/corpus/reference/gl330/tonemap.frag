#version 330
// stereoshift-expect: fragment
// Tonemapping post-process fragment shader: exposure, bloom add, ACES filmic curve and gamma.

in vec2 vUV;

uniform sampler2D uHdrColor;
uniform sampler2D uBloom;
uniform float uExposure;
uniform float uBloomStrength;

out vec4 fragColor;

vec3 acesFilm(vec3 x)
{
    const float a = 2.51;
    const float b = 0.03;
    const float c = 2.43;
    const float d = 0.59;
    const float e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

void main()
{
    vec3 hdr = texture(uHdrColor, vUV).rgb;
    hdr += texture(uBloom, vUV).rgb * uBloomStrength;
    vec3 mapped = acesFilm(hdr * uExposure);
    fragColor = vec4(pow(mapped, vec3(1.0 / 2.2)), 1.0);
}
