#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform UBO
{
    mat4 projection;
    mat4 model;
    mat4 view;
    vec3 camPos;
} ubo;

layout(set = 0, binding = 6, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) in vec3 inPos;
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 1) in vec3 inNormal;
layout(location = 2) out vec2 outUV;
layout(location = 2) in vec2 inUV;

void main()
{
    vec3 locPos = vec3((ubo.model * vec4(inPos, 1.0)).xyz);
    outWorldPos = locPos;
    outNormal = mat3(ubo.model[0].xyz, ubo.model[1].xyz, ubo.model[2].xyz) * inNormal;
    outUV = inUV;
    mat4 _68 = ubo.projection * ubo.view;
    vec4 _73 = vec4(outWorldPos, 1.0);
    vec4 _74 = _68 * _73;
    gl_Position = _74;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _106 = gl_Position.w - stereo.convergence;
        precise float _107 = stereo.eyeSign * stereo.separation;
        precise float _108 = _107 * _106;
        precise float _109 = gl_Position.x + _108;
        gl_Position.x = _109;
    }
}

