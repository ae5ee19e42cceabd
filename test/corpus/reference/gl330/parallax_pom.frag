#version 330
// stereoshift-expect: fragment
// Parallax-occlusion-mapping fragment shader: ray-marches the height map along the interpolated tangent-space view vector.

in vec2 vTexCoord;
in vec3 vViewTS;
in vec3 vLightTS;

uniform sampler2D uHeightMap;
uniform sampler2D uAlbedoMap;
uniform sampler2D uNormalMap;
uniform float uHeightScale;

out vec4 fragColor;

vec2 parallaxOcclusion(vec2 uv, vec3 viewTS)
{
    float layers = mix(32.0, 8.0, abs(viewTS.z));
    float layerDepth = 1.0 / layers;
    vec2 delta = viewTS.xy / viewTS.z * uHeightScale / layers;

    float current = 0.0;
    float sampled = 1.0 - texture(uHeightMap, uv).r;
    while (current < sampled) {
        uv -= delta;
        sampled = 1.0 - texture(uHeightMap, uv).r;
        current += layerDepth;
    }
    vec2 prevUV = uv + delta;
    float after = sampled - current;
    float before = (1.0 - texture(uHeightMap, prevUV).r) - current + layerDepth;
    float w = after / (after - before);
    return mix(uv, prevUV, w);
}

void main()
{
    vec3 v = normalize(vViewTS);
    vec2 uv = parallaxOcclusion(vTexCoord, v);
    if (uv.x < 0.0 || uv.y < 0.0 || uv.x > 1.0 || uv.y > 1.0)
        discard;

    vec3 n = normalize(texture(uNormalMap, uv).xyz * 2.0 - 1.0);
    float diffuse = max(dot(n, normalize(vLightTS)), 0.0);
    fragColor = vec4(texture(uAlbedoMap, uv).rgb * (0.1 + diffuse), 1.0);
}
