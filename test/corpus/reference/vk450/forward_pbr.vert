#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform CameraUBO
{
    mat4 view;
    mat4 proj;
    vec4 cameraPos;
} camera;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(push_constant, std430) uniform PushConstants
{
    mat4 model;
    vec4 tint;
} pc;

layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 1) in vec3 inNormal;
layout(location = 2) out vec2 outUV;
layout(location = 2) in vec2 inUV;

void main()
{
    vec4 world = pc.model * vec4(inPosition, 1.0);
    outWorldPos = world.xyz;
    outNormal = mat3(pc.model[0].xyz, pc.model[1].xyz, pc.model[2].xyz) * inNormal;
    outUV = inUV;
    mat4 _68 = camera.proj * camera.view;
    vec4 _70 = _68 * world;
    gl_Position = _70;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _103 = gl_Position.w - stereo.convergence;
        precise float _104 = stereo.eyeSign * stereo.separation;
        precise float _105 = _104 * _103;
        precise float _106 = gl_Position.x + _105;
        gl_Position.x = _106;
    }
}

