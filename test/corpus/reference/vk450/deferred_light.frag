#version 450

layout(set = 0, binding = 0, std140) uniform FrameUBO
{
    mat4 invViewProj;
    vec4 viewportSize;
    vec4 sunDirection;
    vec4 sunColor;
} frame;

layout(set = 1, binding = 4, std140) uniform ShadowUBO
{
    mat4 lightViewProj;
} shadow;

layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(set = 1, binding = 2) uniform sampler2D gDepth;
layout(set = 1, binding = 3) uniform sampler2DShadow shadowMap;
layout(input_attachment_index = 0, set = 1, binding = 0) uniform subpassInput gAlbedo;
layout(input_attachment_index = 1, set = 1, binding = 1) uniform subpassInput gNormal;

layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;

void main()
{
    float depth = texture(gDepth, inUV).x;
    vec2 ndc = ((gl_FragCoord.xy * frame.viewportSize.zw) * 2.0) - vec2(1.0);
    vec4 _56 = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec4 q = mix(_56, _56 - (frame.invViewProj[0] * ((stereo.eyeSign * stereo.separation) * (1.0 - (stereo.convergence * _56.w)))), bvec4(stereo.eyeSign != 0.0));
    vec3 p = q.xyz / vec3(q.w);
    vec4 lightClip = shadow.lightViewProj * vec4(p, 1.0);
    vec3 shadowCoord = vec3(((lightClip.xy / vec2(lightClip.w)) * 0.5) + vec2(0.5), lightClip.z / lightClip.w);
    float lit = texture(shadowMap, vec3(shadowCoord.xy, shadowCoord.z));
    vec3 albedo = subpassLoad(gAlbedo).xyz;
    vec3 n = normalize((subpassLoad(gNormal).xyz * 2.0) - vec3(1.0));
    float ndl = max(dot(n, -frame.sunDirection.xyz), 0.0);
    outColor = vec4(((albedo * frame.sunColor.xyz) * ndl) * lit, 1.0);
}

