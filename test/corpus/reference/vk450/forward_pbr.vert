#version 450
// stereoshift-expect: shift
// Vulkan forward PBR vertex shader: camera UBO at set 0, per-object model matrix in a push-constant block.

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 view;
    mat4 proj;
    vec4 cameraPos;
} camera;

layout(push_constant) uniform PushConstants {
    mat4 model;
    vec4 tint;
} pc;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUV;

void main_stereoshift_mono()
{
    vec4 world = pc.model * vec4(inPosition, 1.0);
    outWorldPos = world.xyz;
    outNormal = mat3(pc.model) * inNormal;
    outUV = inUV;
    gl_Position = camera.proj * camera.view * world;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
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
