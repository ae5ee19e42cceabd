#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform ShadowUBO
{
    mat4 lightViewProj[4];
    vec4 cascadeSplits;
} shadow;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(push_constant, std430) uniform ShadowPush
{
    mat4 model;
    int cascadeIndex;
} push;

layout(location = 0) out vec2 outUV;
layout(location = 1) in vec2 inUV;
layout(location = 0) in vec3 inPosition;

void main()
{
    outUV = inUV;
    mat4 _41 = shadow.lightViewProj[push.cascadeIndex] * push.model;
    vec4 _50 = vec4(inPosition, 1.0);
    vec4 _51 = _41 * _50;
    gl_Position = _51;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _85 = gl_Position.w - stereo.convergence;
        precise float _86 = stereo.eyeSign * stereo.separation;
        precise float _87 = _86 * _85;
        precise float _88 = gl_Position.x + _87;
        gl_Position.x = _88;
    }
}

