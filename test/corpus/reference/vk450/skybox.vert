#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform SkyUBO
{
    mat4 viewRotation;
    mat4 proj;
    float rotationY;
} sky;

layout(set = 0, binding = 3, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 outDirection;

void main()
{
    float c = cos(sky.rotationY);
    float s = sin(sky.rotationY);
    vec3 dir = vec3((c * inPosition.x) + (s * inPosition.z), inPosition.y, ((-s) * inPosition.x) + (c * inPosition.z));
    outDirection = dir;
    vec4 pos = (sky.proj * sky.viewRotation) * vec4(inPosition, 1.0);
    gl_Position = pos.xyww;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _112 = gl_Position.w - stereo.convergence;
        precise float _113 = stereo.eyeSign * stereo.separation;
        precise float _114 = _113 * _112;
        precise float _115 = gl_Position.x + _114;
        gl_Position.x = _115;
    }
}

