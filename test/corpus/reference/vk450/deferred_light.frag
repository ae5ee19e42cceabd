#version 450
// stereoshift-expect: deferred-unproject
// Vulkan deferred lighting fragment shader: NDC from gl_FragCoord, Vulkan [0,1] depth, world position through the inverse view-projection.

layout(set = 0, binding = 0) uniform FrameUBO {
    mat4 invViewProj;
    vec4 viewportSize;   // xy = pixels, zw = 1 / pixels
    vec4 sunDirection;
    vec4 sunColor;
} frame;

layout(input_attachment_index = 0, set = 1, binding = 0) uniform subpassInput gAlbedo;
layout(input_attachment_index = 1, set = 1, binding = 1) uniform subpassInput gNormal;
layout(set = 1, binding = 2) uniform sampler2D gDepth;
layout(set = 1, binding = 3) uniform sampler2DShadow shadowMap;

layout(set = 1, binding = 4) uniform ShadowUBO {
    mat4 lightViewProj;
} shadow;

layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;

/* ---- stereoshift ---- */ vec4 stereoshift_unproject_frame_invViewProj(vec4 stereoshift_q); /* ---- end stereoshift ---- */ void main()
{
    float depth = texture(gDepth, inUV).r;
    vec2 ndc = gl_FragCoord.xy * frame.viewportSize.zw * 2.0 - 1.0;
    vec4 q = stereoshift_unproject_frame_invViewProj(frame.invViewProj * vec4(ndc, depth, 1.0));
    vec3 p = q.xyz / q.w;

    vec4 lightClip = shadow.lightViewProj * vec4(p, 1.0);
    vec3 shadowCoord = vec3(lightClip.xy / lightClip.w * 0.5 + 0.5, lightClip.z / lightClip.w);
    float lit = texture(shadowMap, shadowCoord);

    vec3 albedo = subpassLoad(gAlbedo).rgb;
    vec3 n = normalize(subpassLoad(gNormal).xyz * 2.0 - 1.0);
    float ndl = max(dot(n, -frame.sunDirection.xyz), 0.0);
    outColor = vec4(albedo * frame.sunColor.rgb * ndl * lit, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_unproject_frame_invViewProj(vec4 stereoshift_q)
{
    return stereo.eyeSign != 0.0 ? stereoshift_q - frame.invViewProj[0] * ((stereo.eyeSign * stereo.separation) * (1.0 - stereo.convergence * stereoshift_q.w)) : stereoshift_q;
}
// ---- end stereoshift ----
