#version 300 es
// stereoshift-expect: fragment
// Water-surface fragment shader: refraction of the scene colour at screen UVs distorted by a normal map.

precision mediump float;

in highp vec4 vClipPos;
in highp vec2 vScreenUV;
in vec2 vTexCoord;
in vec3 vNormal;

uniform sampler2D uSceneColor;
uniform sampler2D uWaveNormals;
uniform vec3 uWaterColor;
uniform float uDistortion;

out vec4 fragColor;

void main()
{
    vec3 detail = texture(uWaveNormals, vTexCoord).xyz * 2.0 - 1.0;
    vec3 n = normalize(vNormal + vec3(detail.x, 0.0, detail.y));
    // Per-pixel screen UV from the interpolated clip position, then distort.
    highp vec2 screenUV = vClipPos.xy / vClipPos.w * 0.5 + 0.5;
    vec2 uv = mix(vScreenUV, screenUV, 0.5) + n.xz * uDistortion;
    vec3 refracted = texture(uSceneColor, clamp(uv, 0.001, 0.999)).rgb;
    float fresnel = pow(1.0 - max(n.y, 0.0), 3.0);
    fragColor = vec4(mix(refracted * uWaterColor, vec3(0.8, 0.9, 1.0), fresnel), 1.0);
}
