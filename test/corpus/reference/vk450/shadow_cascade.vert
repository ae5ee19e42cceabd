#version 450
// stereoshift-expect: shift
// Cascaded shadow-map vertex shader: light view-projection per cascade selected by a push constant (mono pass).

const int CASCADE_COUNT = 4;

layout(set = 0, binding = 0) uniform ShadowUBO {
    mat4 lightViewProj[CASCADE_COUNT];
    vec4 cascadeSplits;
} shadow;

layout(push_constant) uniform ShadowPush {
    mat4 model;
    int cascadeIndex;
} push;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUV;

layout(location = 0) out vec2 outUV;

void main_stereoshift_mono()
{
    outUV = inUV;
    gl_Position = shadow.lightViewProj[push.cascadeIndex] * push.model * vec4(inPosition, 1.0);
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
