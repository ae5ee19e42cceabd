#version 450
// stereoshift-expect: deferred-unproject
// Deferred decal fragment shader: screen UV from the interpolated clip position, depth unprojected with the inverse view-projection into decal space.

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 viewProj;
    mat4 invViewProj;
} camera;

// 80 bytes: within the 128 bytes of push constants every Vulkan device guarantees.
layout(push_constant) uniform DecalPush {
    mat4 decalToWorld;
    vec4 color;
} decal;

layout(set = 1, binding = 2) uniform DecalUBO {
    mat4 worldToDecal;
} decalSpace;

layout(set = 1, binding = 0) uniform sampler2D sceneDepth;
layout(set = 1, binding = 1) uniform sampler2D decalTexture;

layout(location = 0) in vec4 inClipPos;
layout(location = 0) out vec4 outAlbedo;

/* ---- stereoshift ---- */ vec4 stereoshift_unproject_camera_invViewProj(vec4 stereoshift_q); /* ---- end stereoshift ---- */ void main()
{
    vec2 ndc = inClipPos.xy / inClipPos.w;
    vec2 screenUV = ndc * 0.5 + 0.5;
    float depth = texture(sceneDepth, screenUV).r;

    vec4 q = stereoshift_unproject_camera_invViewProj(camera.invViewProj * vec4(ndc, depth, 1.0));
    vec3 world = q.xyz / q.w;
    vec3 local = (decalSpace.worldToDecal * vec4(world, 1.0)).xyz;
    if (any(greaterThan(abs(local), vec3(0.5))))
        discard;

    vec4 texel = texture(decalTexture, local.xz + 0.5);
    outAlbedo = vec4(texel.rgb * decal.color.rgb, texel.a * decal.color.a);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
layout(set = 0, binding = 1, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_unproject_camera_invViewProj(vec4 stereoshift_q)
{
    return stereo.eyeSign != 0.0 ? stereoshift_q - camera.invViewProj[0] * ((stereo.eyeSign * stereo.separation) * (1.0 - stereo.convergence * stereoshift_q.w)) : stereoshift_q;
}
// ---- end stereoshift ----
