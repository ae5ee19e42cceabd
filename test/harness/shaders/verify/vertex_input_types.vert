// Vertex inputs of every shape a vertex buffer carries: integer bone indices, a uint flag vector,
// an instance matrix (four locations), an array of weights (four locations) and a double position.
#version 450

layout (set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout (set = 0, binding = 1) uniform Skin { mat4 bones[4]; } skin;

layout (location = 0) in ivec4 inBoneIds;
layout (location = 1) in uvec2 inFlags;
layout (location = 2) in mat4 inInstanceModel;
layout (location = 6) in float inWeights[4];
layout (location = 10) in dvec3 inPrecisePos;

layout (location = 0) flat out uint outFlags;

void main() {
	mat4 skinMat = skin.bones[inBoneIds.x] * inWeights[0] + skin.bones[inBoneIds.y] * inWeights[1]
	             + skin.bones[inBoneIds.z] * inWeights[2] + skin.bones[inBoneIds.w] * inWeights[3];
	vec3 pos = vec3(inPrecisePos);
	outFlags = inFlags.x | inFlags.y;
	gl_Position = camera.viewProj * inInstanceModel * (0.25 * skinMat + mat4(1.0)) * vec4(pos, 1.0);
}
