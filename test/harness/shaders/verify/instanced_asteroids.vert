// Vulkan GLSL instancing with a per-instance mat4 attribute (four locations) and a per-instance
// scale, camera in a uniform block: an asteroid field.
#version 450
layout (location = 0) in vec3 inPos;
layout (location = 1) in vec3 inNormal;
layout (location = 2) in vec2 inUV;
layout (location = 3) in mat4 instanceModel;
layout (location = 7) in float instanceScale;

layout (set = 0, binding = 0) uniform Camera
{
	mat4 projection;
	mat4 view;
	vec4 lightDir;
} camera;

layout (location = 0) out vec3 outNormal;
layout (location = 1) out vec2 outUV;
layout (location = 2) out float outLight;

void main()
{
	vec4 world = instanceModel * vec4(inPos * instanceScale, 1.0);
	outNormal = mat3(instanceModel) * inNormal;
	outUV = inUV;
	outLight = max(dot(normalize(outNormal), -camera.lightDir.xyz), 0.0);
	gl_Position = camera.projection * camera.view * world;
}
