#version 450

layout(set = 0, binding = 0, std140) uniform View
{
    mat4 invProjection;
    vec4 screenSize;
    vec4 lightPosRadius;
    vec4 lightColor;
} view;

layout(set = 0, binding = 3, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(set = 0, binding = 1) uniform sampler2D linearDepthBuffer;
layout(set = 0, binding = 2) uniform sampler2D normalBuffer;

layout(location = 0) out vec4 outColor;

void main()
{
    vec2 uv = gl_FragCoord.xy * view.screenSize.zw;
    vec4 farPlane = view.invProjection * vec4((uv * 2.0) - vec2(1.0), 1.0, 1.0);
    vec3 viewRay = farPlane.xyz / vec3(farPlane.w);
    float viewDepth = texture(linearDepthBuffer, uv).x;
    vec3 _72 = viewRay * (viewDepth / (-viewRay.z));
    float _136 = _72.z;
    vec3 _146 = _72;
    _146.x = _72.x - (((stereo.eyeSign * stereo.separation) * (((_136 < 0.0) ? (-_136) : _136) - stereo.convergence)) * view.invProjection[0].x);
    vec3 viewPos = mix(_72, _146, bvec3(stereo.eyeSign != 0.0));
    vec3 n = normalize((texture(normalBuffer, uv).xyz * 2.0) - vec3(1.0));
    vec3 toLight = view.lightPosRadius.xyz - viewPos;
    float dist = length(toLight);
    float atten = clamp(1.0 - (dist / view.lightPosRadius.w), 0.0, 1.0);
    outColor = vec4(((view.lightColor.xyz * max(dot(n, toLight / vec3(dist)), 0.0)) * atten) * atten, 1.0);
}

