#version 450
// stereoshift-expect: fragment
// Terrain fragment shader: height-blended grass/rock/snow layers with normals from height-map differences.

layout(set = 0, binding = 1) uniform sampler2D heightMap;
layout(set = 1, binding = 0) uniform sampler2DArray layerTextures;

layout(set = 1, binding = 1) uniform TerrainShading {
    vec4 sunDir;
    vec4 layerHeights;   // x = rock start, y = snow start
    float detailTiling;
} shading;

layout(location = 0) in vec2 inUV;
layout(location = 1) in float inHeight;

layout(location = 0) out vec4 outColor;

void main()
{
    vec2 texel = 1.0 / vec2(textureSize(heightMap, 0));
    float hl = texture(heightMap, inUV - vec2(texel.x, 0.0)).r;
    float hr = texture(heightMap, inUV + vec2(texel.x, 0.0)).r;
    float hd = texture(heightMap, inUV - vec2(0.0, texel.y)).r;
    float hu = texture(heightMap, inUV + vec2(0.0, texel.y)).r;
    vec3 n = normalize(vec3(hl - hr, 2.0 * texel.x * 64.0, hd - hu));

    vec2 detailUV = inUV * shading.detailTiling;
    vec3 grass = texture(layerTextures, vec3(detailUV, 0.0)).rgb;
    vec3 rock = texture(layerTextures, vec3(detailUV, 1.0)).rgb;
    vec3 snow = texture(layerTextures, vec3(detailUV, 2.0)).rgb;
    vec3 albedo = mix(grass, rock, smoothstep(shading.layerHeights.x, shading.layerHeights.x + 0.05, inHeight));
    albedo = mix(albedo, snow, smoothstep(shading.layerHeights.y, shading.layerHeights.y + 0.05, inHeight));

    float ndl = max(dot(n, -shading.sunDir.xyz), 0.0);
    outColor = vec4(albedo * (0.15 + 0.85 * ndl), 1.0);
}
