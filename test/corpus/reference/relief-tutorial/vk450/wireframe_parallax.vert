#version 450
// stereoshift-expect: per-eye-view
// Parallax mapping with a wireframe overlay, vertex stage: loose tangent-space varyings by location, camera from a uniform block.
layout (location = 0) in vec3 inPos;
layout (location = 1) in vec2 inUV;
layout (location = 2) in vec3 inNormal;
layout (location = 3) in vec4 inTangent;

layout (binding = 0) uniform UBO
{
	mat4 projection;
	mat4 view;
	mat4 model;
	vec4 cameraPos;
} ubo;

layout (location = 0) out vec2 outUV;
layout (location = 1) out vec3 outTangentViewPos;
layout (location = 2) out vec3 outTangentFragPos;

/* ---- stereoshift ---- */ vec4 stereoshift_eye_ubo_cameraPos(vec4 stereoshift_camera); /* ---- end stereoshift ---- */ void main()
{
	vec3 worldPos = vec3(ubo.model * vec4(inPos, 1.0));
	vec3 N = normalize(mat3(ubo.model) * inNormal);
	vec3 T = normalize(mat3(ubo.model) * inTangent.xyz);
	vec3 B = normalize(cross(N, T)) * inTangent.w;
	mat3 TBN = transpose(mat3(T, B, N));
	outUV = inUV;
	outTangentViewPos = TBN * stereoshift_eye_ubo_cameraPos(ubo.cameraPos).xyz;
	outTangentFragPos = TBN * worldPos;
	gl_Position = ubo.projection * ubo.view * vec4(worldPos, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
layout(set = 0, binding = 5, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_eye_ubo_cameraPos(vec4 stereoshift_camera)
{
    return stereoshift_camera + vec4((inverse(ubo.projection * ubo.view) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
}
// ---- end stereoshift ----
