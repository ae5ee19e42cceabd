// Arrays of uniform blocks and of samplers, and bone matrices fetched from a texel buffer.
#version 450

layout (set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout (set = 0, binding = 1) uniform Light {
	mat4 lightSpace;
	vec4 position;
} lights[3];
layout (set = 0, binding = 2) uniform sampler2D detailMaps[2];
layout (set = 0, binding = 3) uniform samplerBuffer boneTexels;

layout (location = 0) in vec3 inPos;
layout (location = 1) in vec2 inUV;

layout (location = 0) out vec4 outLightCoord0;
layout (location = 1) out vec4 outLightCoord2;
layout (location = 2) out float outDetail;

void main() {
	mat4 bone = mat4(1.0);
	bone[3] = vec4(texelFetch(boneTexels, 3).xyz * 0.1, 1.0);
	vec4 world = bone * vec4(inPos, 1.0);
	outLightCoord0 = lights[0].lightSpace * world;
	outLightCoord2 = lights[2].lightSpace * world + lights[1].position;
	outDetail = textureLod(detailMaps[0], inUV, 0.0).r + textureLod(detailMaps[1], inUV, 0.0).g;
	gl_Position = camera.viewProj * world;
}
