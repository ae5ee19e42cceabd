#version 450
// stereoshift-expect: fragment
// Parallax mapping with a wireframe overlay, fragment stage: steep parallax along the view direction, edges darkened from the geometry stage's distances.
layout (binding = 2) uniform sampler2D sColorMap;
layout (binding = 3) uniform sampler2D sHeightMap;

layout (binding = 4) uniform Material
{
	float heightScale;
	float numLayers;
} material;

layout (location = 0) in vec2 inUV;
layout (location = 1) in vec3 inTangentViewPos;
layout (location = 2) in vec3 inTangentFragPos;
layout (location = 3) noperspective in vec3 inEdgeDistance;

layout (location = 0) out vec4 outColor;

vec2 steepParallax(vec2 uv, vec3 viewDir)
{
	float layerDepth = 1.0 / material.numLayers;
	float currLayerDepth = 0.0;
	vec2 deltaUV = viewDir.xy * material.heightScale / (viewDir.z * material.numLayers);
	vec2 currUV = uv;
	float height = 1.0 - texture(sHeightMap, currUV).r;
	for (int i = 0; i < int(material.numLayers); i++) {
		if (height < currLayerDepth)
			break;
		currLayerDepth += layerDepth;
		currUV -= deltaUV;
		height = 1.0 - texture(sHeightMap, currUV).r;
	}
	return currUV;
}

void main()
{
	vec3 V = normalize(inTangentViewPos - inTangentFragPos);
	vec2 uv = steepParallax(inUV, V);
	float edge = min(inEdgeDistance.x, min(inEdgeDistance.y, inEdgeDistance.z));
	float line = 1.0 - smoothstep(0.5, 1.5, edge);
	outColor = vec4(mix(texture(sColorMap, uv).rgb, vec3(0.05), line), 1.0);
}
