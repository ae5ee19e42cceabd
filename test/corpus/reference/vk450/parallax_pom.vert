#version 450
// stereoshift-expect: per-eye-view
// Vulkan parallax-occlusion vertex shader: tangent-space view vector from camera.cameraPosition (shared include) minus world position.

#extension GL_GOOGLE_include_directive : require

#include "common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUV;

layout(location = 0) out vec2 outUV;
layout(location = 1) out vec3 outWorldPos;
layout(location = 2) out vec3 outViewTS;
layout(location = 3) out mat3 outWorldToTangent;   // occupies locations 3..5

/* ---- stereoshift ---- */ vec4 stereoshift_eye_camera_cameraPosition(vec4 stereoshift_camera); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
{
    vec4 world = object.model * vec4(inPosition, 1.0);
    vec3 n = normalize(mat3(object.model) * inNormal);
    vec3 t = normalize(mat3(object.model) * inTangent.xyz);
    mat3 worldToTangent = buildWorldToTangent(n, t, inTangent.w);

    outUV = inUV;
    outWorldPos = world.xyz;
    outViewTS = worldToTangent * (stereoshift_eye_camera_cameraPosition(camera.cameraPosition).xyz - world.xyz);
    outWorldToTangent = worldToTangent;
    gl_Position = camera.viewProj * world;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_eye_camera_cameraPosition(vec4 stereoshift_camera)
{
    return stereoshift_camera + vec4((camera.invViewProj * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
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
