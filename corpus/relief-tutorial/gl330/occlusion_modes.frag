#version 330 core
// stereoshift-expect: fragment
// Parallax demo with selectable modes, fragment stage: a switch between plain, steep and occlusion parallax.
in vec2 vUV;
in vec3 vTangentEye;
in vec3 vTangentPos;

out vec4 outColor;

uniform sampler2D uAlbedo;
uniform sampler2D uHeight;
uniform float uScale;
uniform int uMode;

vec2 occlusionParallax(vec2 uv, vec3 v)
{
    float layers = 24.0;
    float step = 1.0 / layers;
    vec2 delta = v.xy * uScale / (v.z * layers);
    float depth = 0.0;
    float h = 1.0 - texture(uHeight, uv).r;
    for (int i = 0; i < 24; ++i) {
        if (depth >= h) break;
        uv -= delta;
        h = 1.0 - texture(uHeight, uv).r;
        depth += step;
    }
    vec2 before = uv + delta;
    float a = h - depth;
    float b = 1.0 - texture(uHeight, before).r - depth + step;
    return mix(uv, before, a / (a - b));
}

void main()
{
    vec3 v = normalize(vTangentEye - vTangentPos);
    vec2 uv = vUV;
    switch (uMode) {
    case 0:
        break;
    case 1:
        uv -= v.xy * (texture(uHeight, vUV).r * uScale);
        break;
    default:
        uv = occlusionParallax(vUV, v);
        break;
    }
    outColor = texture(uAlbedo, uv);
}
