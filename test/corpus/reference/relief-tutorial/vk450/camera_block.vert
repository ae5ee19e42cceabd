#version 450

invariant gl_Position;

struct CameraData
{
    mat4 view;
    mat4 projection;
    vec4 position;
};

layout(set = 0, binding = 0, std140) uniform CameraBuffer
{
    CameraData camera;
} _15;

layout(set = 1, binding = 0, std140) uniform ObjectBuffer
{
    mat4 model;
} object;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 0) out vec2 outTexCoord;
layout(location = 3) in vec2 inTexCoord;
layout(location = 1) out vec3 outTangentEye;
layout(location = 2) out vec3 outTangentPosition;

void main()
{
    CameraData _174 = _15.camera;
    _174.position = _174.position + vec4((inverse(_15.camera.projection * _15.camera.view) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0);
    CameraData cam;
    cam.view = _174.view;
    cam.projection = _174.projection;
    cam.position = _174.position;
    vec4 world = object.model * vec4(inPosition, 1.0);
    vec3 n = normalize(mat3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * inNormal);
    vec3 t = normalize(mat3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * inTangent.xyz);
    mat3 worldToTangent = transpose(mat3(vec3(t), vec3(cross(n, t) * inTangent.w), vec3(n)));
    outTexCoord = inTexCoord;
    outTangentEye = worldToTangent * cam.position.xyz;
    outTangentPosition = worldToTangent * world.xyz;
    mat4 _135 = cam.projection * cam.view;
    vec4 _137 = _135 * world;
    gl_Position = _137;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _168 = gl_Position.w - stereo.convergence;
        precise float _169 = stereo.eyeSign * stereo.separation;
        precise float _170 = _169 * _168;
        precise float _171 = gl_Position.x + _170;
        gl_Position.x = _171;
    }
}

