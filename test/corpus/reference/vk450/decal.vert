#version 450
// stereoshift-expect: shift
// Deferred decal box vertex shader: projects the decal volume and also copies the clip position to a varying (halo case).

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 viewProj;
    mat4 invViewProj;
} camera;

// 80 bytes: within the 128 bytes of push constants every Vulkan device guarantees.
layout(push_constant) uniform DecalPush {
    mat4 decalToWorld;
    vec4 color;
} decal;

layout(location = 0) in vec3 inPosition;   // unit cube in [-0.5, 0.5]

layout(location = 0) out vec4 outClipPos;

void main_stereoshift_mono()
{
    vec4 world = decal.decalToWorld * vec4(inPosition, 1.0);
    gl_Position = camera.viewProj * world;
    outClipPos = gl_Position;
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
    outClipPos = gl_Position;
}
// ---- end stereoshift ----
