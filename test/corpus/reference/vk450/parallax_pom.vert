#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform CameraBlock
{
    mat4 view;
    mat4 proj;
    mat4 viewProj;
    mat4 invViewProj;
    vec4 cameraPosition;
    vec4 viewportSize;
} camera;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(push_constant, std430) uniform ObjectPush
{
    mat4 model;
    uint materialIndex;
} object;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 0) out vec2 outUV;
layout(location = 3) in vec2 inUV;
layout(location = 1) out vec3 outWorldPos;
layout(location = 2) out vec3 outViewTS;
layout(location = 3) out mat3 outWorldToTangent;

mat3 buildWorldToTangent(vec3 n, vec3 t, float handedness)
{
    vec3 b = cross(n, t) * handedness;
    return transpose(mat3(vec3(t), vec3(b), vec3(n)));
}

void main()
{
    vec4 world = object.model * vec4(inPosition, 1.0);
    vec3 n = normalize(mat3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * inNormal);
    vec3 t = normalize(mat3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * inTangent.xyz);
    vec3 param = n;
    vec3 param_1 = t;
    float param_2 = inTangent.w;
    mat3 worldToTangent = buildWorldToTangent(param, param_1, param_2);
    outUV = inUV;
    outWorldPos = world.xyz;
    outViewTS = worldToTangent * ((camera.cameraPosition + vec4((camera.invViewProj * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0)).xyz - world.xyz);
    outWorldToTangent = worldToTangent;
    vec4 _144 = camera.viewProj * world;
    gl_Position = _144;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _176 = gl_Position.w - stereo.convergence;
        precise float _177 = stereo.eyeSign * stereo.separation;
        precise float _178 = _177 * _176;
        precise float _179 = gl_Position.x + _178;
        gl_Position.x = _179;
    }
}

