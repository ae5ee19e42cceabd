// Instanced drawing from a storage buffer of transforms plus a height field read as a storage
// image, as GPU-driven samples do.
#version 450

struct InstanceData {
	mat4 model;
	vec4 color;
};

layout (set = 0, binding = 0) uniform Camera {
	mat4 projection;
	mat4 view;
} camera;

layout (std430, set = 0, binding = 1) readonly buffer Instances {
	InstanceData instances[];
};

layout (set = 0, binding = 2, rgba32f) uniform readonly image2D heightField;
layout (set = 0, binding = 3, r32f) uniform readonly image2D wetness;

layout (location = 0) in vec3 inPos;
layout (location = 0) out vec4 outColor;

void main() {
	InstanceData instance = instances[gl_VertexIndex % 8];
	float h = imageLoad(heightField, ivec2(gl_VertexIndex % 4, 0)).r + imageLoad(wetness, ivec2(1, 1)).r;
	outColor = instance.color;
	gl_Position = camera.projection * camera.view * instance.model * vec4(inPos + vec3(0.0, h, 0.0), 1.0);
}
