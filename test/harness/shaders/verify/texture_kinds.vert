// Terrain-style vertex shader in the Vulkan-sample manner: layered height maps, an environment
// cube, a 3D noise volume and an integer material map, all read in the vertex stage.
#version 450

layout (set = 0, binding = 0) uniform UBO {
	mat4 projection;
	mat4 view;
	mat4 model;
	float heightScale;
	float noiseScale;
} ubo;

layout (set = 0, binding = 1) uniform sampler2DArray heightLayers;
layout (set = 0, binding = 2) uniform samplerCube envMap;
layout (set = 0, binding = 3) uniform sampler3D noiseVolume;
layout (set = 1, binding = 0) uniform usampler2D materialIds;

layout (location = 0) in vec3 inPos;
layout (location = 1) in vec2 inUV;

layout (location = 0) out vec2 outUV;
layout (location = 1) out vec3 outTint;

void main() {
	uint layer = texelFetch(materialIds, ivec2(0), 0).r;
	float height = textureLod(heightLayers, vec3(inUV, float(layer)), 0.0).r * ubo.heightScale;
	float noise = textureLod(noiseVolume, inPos * 0.1, 0.0).r * ubo.noiseScale;
	outTint = textureLod(envMap, normalize(inPos), 0.0).rgb;
	outUV = inUV;
	vec3 pos = inPos + vec3(0.0, height + noise, 0.0);
	gl_Position = ubo.projection * ubo.view * ubo.model * vec4(pos, 1.0);
}
