#version 450
// stereoshift-expect: per-eye-view
// Parallax-mapping sample, vertex stage: one uniform block with the matrices, light and camera (vec4 members used as .xyz).
layout (location = 0) in vec3 inPos;
layout (location = 1) in vec2 inUV;
layout (location = 2) in vec3 inNormal;
layout (location = 3) in vec4 inTangent;

layout (binding = 0) uniform UBO
{
	mat4 projection;
	mat4 view;
	mat4 model;
	vec4 lightPos;
	vec4 cameraPos;
} ubo;

layout (location = 0) out vec2 outUV;
layout (location = 1) out vec3 outTangentLightPos;
layout (location = 2) out vec3 outTangentViewPos;
layout (location = 3) out vec3 outTangentFragPos;

/* ---- stereoshift ---- */ vec4 stereoshift_eye_ubo_cameraPos(vec4 stereoshift_camera); /* ---- end stereoshift ---- */ void main_stereoshift_mono(void)
{
	gl_Position = ubo.projection * ubo.view * ubo.model * vec4(inPos, 1.0f);
	vec3 outPos = vec3(ubo.model * vec4(inPos, 1.0));
	outUV = inUV;

	vec3 N = normalize(mat3(ubo.model) * inNormal);
	vec3 T = normalize(mat3(ubo.model) * inTangent.xyz);
	vec3 B = normalize(cross(N, T)) * inTangent.w;
	mat3 TBN = transpose(mat3(T, B, N));

	outTangentLightPos = TBN * ubo.lightPos.xyz;
	outTangentViewPos = TBN * stereoshift_eye_ubo_cameraPos(ubo.cameraPos).xyz;
	outTangentFragPos = TBN * outPos;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 4, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_eye_ubo_cameraPos(vec4 stereoshift_camera)
{
    return stereoshift_camera + vec4((inverse(ubo.projection * ubo.view) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
}
void main()
{
    main_stereoshift_mono();
    if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        precise float stereoshift_x = gl_Position.x + (stereo.eyeSign * stereo.separation) * (gl_Position.w - stereo.convergence);
        gl_Position.x = stereoshift_x;
    }
}
// ---- end stereoshift ----
