#version 450

invariant gl_Position;

layout(set = 0, binding = 0, std140) uniform UBO
{
    mat4 projection;
    mat4 view;
    mat4 model;
    vec4 lightPos;
    vec4 cameraPos;
} ubo;

layout(set = 0, binding = 4, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(location = 0) in vec3 inPos;
layout(location = 0) out vec2 outUV;
layout(location = 1) in vec2 inUV;
layout(location = 2) in vec3 inNormal;
layout(location = 3) in vec4 inTangent;
layout(location = 1) out vec3 outTangentLightPos;
layout(location = 2) out vec3 outTangentViewPos;
layout(location = 3) out vec3 outTangentFragPos;

void main()
{
    mat4 _26 = ubo.projection * ubo.view;
    mat4 _30 = _26 * ubo.model;
    vec4 _39 = vec4(inPos, 1.0);
    vec4 _40 = _30 * _39;
    gl_Position = _40;
    vec3 outPos = vec3((ubo.model * vec4(inPos, 1.0)).xyz);
    outUV = inUV;
    vec3 N = normalize(mat3(ubo.model[0].xyz, ubo.model[1].xyz, ubo.model[2].xyz) * inNormal);
    vec3 T = normalize(mat3(ubo.model[0].xyz, ubo.model[1].xyz, ubo.model[2].xyz) * inTangent.xyz);
    vec3 B = normalize(cross(N, T)) * inTangent.w;
    mat3 TBN = transpose(mat3(vec3(T), vec3(B), vec3(N)));
    outTangentLightPos = TBN * ubo.lightPos.xyz;
    outTangentViewPos = TBN * (ubo.cameraPos + vec4((inverse(ubo.projection * ubo.view) * vec4((stereo.eyeSign * stereo.separation) * stereo.convergence, 0.0, 0.0, 0.0)).xyz, 0.0)).xyz;
    outTangentFragPos = TBN * outPos;
    if ((stereo.eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        precise float _172 = gl_Position.w - stereo.convergence;
        precise float _173 = stereo.eyeSign * stereo.separation;
        precise float _174 = _173 * _172;
        precise float _175 = gl_Position.x + _174;
        gl_Position.x = _175;
    }
}

