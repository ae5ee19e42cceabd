#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform CameraUBO
{
    mat4 viewProj;
    mat4 invViewProj;
} camera;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(push_constant, std430) uniform DecalPush
{
    mat4 decalToWorld;
    vec4 color;
} decal;

layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec4 outClipPos;

void main()
{
    vec4 world = decal.decalToWorld * vec4(inPosition, 1.0);
    vec4 _42 = camera.viewProj * world;
    gl_Position = _42;
    vec4 _47 = gl_Position;
    precise float _62 = _47.w - stereo.convergence;
    precise float _63 = stereo.eyeSign * stereo.separation;
    precise float _64 = _63 * _62;
    precise float _65 = _47.x + _64;
    _47.x = ((stereo.eyeSign != 0.0) && ((abs(_47.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(_47.w)))) ? _65 : _47.x;
    outClipPos = _47;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _103 = gl_Position.w - stereo.convergence;
        precise float _104 = stereo.eyeSign * stereo.separation;
        precise float _105 = _104 * _103;
        precise float _106 = gl_Position.x + _105;
        gl_Position.x = _106;
    }
}

