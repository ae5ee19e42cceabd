#version 450
// stereoshift-expect: shift
// Vulkan skybox vertex shader: cube vertices at infinity, gl_Position = pos.xyww so depth lands on the far plane.

layout(set = 0, binding = 0) uniform SkyUBO {
    mat4 viewRotation;   // view matrix with the translation removed
    mat4 proj;
    float rotationY;
} sky;

layout(location = 0) in vec3 inPosition;

layout(location = 0) out vec3 outDirection;

void main_stereoshift_mono()
{
    float c = cos(sky.rotationY);
    float s = sin(sky.rotationY);
    vec3 dir = vec3(c * inPosition.x + s * inPosition.z, inPosition.y, -s * inPosition.x + c * inPosition.z);
    outDirection = dir;

    vec4 pos = sky.proj * sky.viewRotation * vec4(inPosition, 1.0);
    gl_Position = pos.xyww;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
layout(set = 0, binding = 3, std140) uniform StereoParams
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
