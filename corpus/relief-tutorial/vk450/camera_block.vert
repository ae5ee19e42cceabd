#version 450
// stereoshift-expect: per-eye-view
// Relief-mapped decal, vertex stage: the camera block is copied whole into a local struct before use.
struct CameraData
{
	mat4 view;
	mat4 projection;
	vec4 position;
};

layout (set = 0, binding = 0) uniform CameraBuffer { CameraData camera; };
layout (set = 1, binding = 0) uniform ObjectBuffer { mat4 model; } object;

layout (location = 0) in vec3 inPosition;
layout (location = 1) in vec3 inNormal;
layout (location = 2) in vec4 inTangent;
layout (location = 3) in vec2 inTexCoord;

layout (location = 0) out vec2 outTexCoord;
layout (location = 1) out vec3 outTangentEye;
layout (location = 2) out vec3 outTangentPosition;

void main()
{
	CameraData cam = camera;
	vec4 world = object.model * vec4(inPosition, 1.0);
	vec3 n = normalize(mat3(object.model) * inNormal);
	vec3 t = normalize(mat3(object.model) * inTangent.xyz);
	mat3 worldToTangent = transpose(mat3(t, cross(n, t) * inTangent.w, n));
	outTexCoord = inTexCoord;
	outTangentEye = worldToTangent * cam.position.xyz;
	outTangentPosition = worldToTangent * world.xyz;
	gl_Position = cam.projection * cam.view * world;
}
