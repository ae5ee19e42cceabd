#version 450
// stereoshift-expect: fragment
// Parallax-mapping sample, fragment stage: the mapping mode is chosen at run time (none, plain, steep, occlusion).
layout (binding = 1) uniform sampler2D sColorMap;
layout (binding = 2) uniform sampler2D sNormalHeightMap;

layout (binding = 3) uniform UBO
{
	float heightScale;
	float parallaxBias;
	float numLayers;
	int mappingMode;
} ubo;

layout (location = 0) in vec2 inUV;
layout (location = 1) in vec3 inTangentLightPos;
layout (location = 2) in vec3 inTangentViewPos;
layout (location = 3) in vec3 inTangentFragPos;

layout (location = 0) out vec4 outColor;

vec2 plainParallax(vec2 uv, vec3 viewDir)
{
	float height = 1.0 - textureLod(sNormalHeightMap, uv, 0.0).a;
	vec2 p = viewDir.xy * (height * (ubo.heightScale * 0.5) + ubo.parallaxBias) / viewDir.z;
	return uv - p;
}

vec2 steepParallax(vec2 uv, vec3 viewDir)
{
	float layerDepth = 1.0 / ubo.numLayers;
	float currLayerDepth = 0.0;
	vec2 deltaUV = viewDir.xy * ubo.heightScale / (viewDir.z * ubo.numLayers);
	vec2 currUV = uv;
	float height = 1.0 - textureLod(sNormalHeightMap, currUV, 0.0).a;
	for (int i = 0; i < int(ubo.numLayers); i++) {
		currLayerDepth += layerDepth;
		currUV -= deltaUV;
		height = 1.0 - textureLod(sNormalHeightMap, currUV, 0.0).a;
		if (height < currLayerDepth) {
			break;
		}
	}
	return currUV;
}

vec2 occlusionParallax(vec2 uv, vec3 viewDir)
{
	vec2 currUV = steepParallax(uv, viewDir);
	vec2 deltaUV = viewDir.xy * ubo.heightScale / (viewDir.z * ubo.numLayers);
	vec2 prevUV = currUV + deltaUV;
	float nextDepth = (1.0 - textureLod(sNormalHeightMap, currUV, 0.0).a);
	float prevDepth = (1.0 - textureLod(sNormalHeightMap, prevUV, 0.0).a);
	float weight = nextDepth / (nextDepth - prevDepth + 1e-4);
	return mix(currUV, prevUV, clamp(weight, 0.0, 1.0));
}

void main(void)
{
	vec3 V = normalize(inTangentViewPos - inTangentFragPos);
	vec2 uv = inUV;
	switch (ubo.mappingMode) {
		case 1: uv = plainParallax(inUV, V); break;
		case 2: uv = steepParallax(inUV, V); break;
		case 3: uv = occlusionParallax(inUV, V); break;
		default: break;
	}
	vec3 N = normalize(textureLod(sNormalHeightMap, uv, 0.0).rgb * 2.0 - 1.0);
	vec3 L = normalize(inTangentLightPos - inTangentFragPos);
	vec3 color = texture(sColorMap, uv).rgb;
	outColor = vec4(color * (0.1 + max(dot(N, L), 0.0)), 1.0);
}
