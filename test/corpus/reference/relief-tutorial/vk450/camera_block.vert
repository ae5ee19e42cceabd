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

/* ---- stereoshift ---- */ CameraData stereoshift_holder_camera(CameraData stereoshift_holder); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
{
	CameraData cam = stereoshift_holder_camera(camera);
	vec4 world = object.model * vec4(inPosition, 1.0);
	vec3 n = normalize(mat3(object.model) * inNormal);
	vec3 t = normalize(mat3(object.model) * inTangent.xyz);
	mat3 worldToTangent = transpose(mat3(t, cross(n, t) * inTangent.w, n));
	outTexCoord = inTexCoord;
	outTangentEye = worldToTangent * cam.position.xyz;
	outTangentPosition = worldToTangent * world.xyz;
	gl_Position = cam.projection * cam.view * world;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_eye_camera_position(vec4 stereoshift_camera)
{
    return stereoshift_camera + vec4((inverse(camera.projection * camera.view) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
}
CameraData stereoshift_holder_camera(CameraData stereoshift_holder)
{
    stereoshift_holder.position = stereoshift_eye_camera_position(stereoshift_holder.position);
    return stereoshift_holder;
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
