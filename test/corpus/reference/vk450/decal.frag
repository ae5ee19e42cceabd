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

void main()
{
    vec2 ndc = inClipPos.xy / inClipPos.w;
    vec2 screenUV = ndc * 0.5 + 0.5;
    float depth = texture(sceneDepth, screenUV).r;

    vec4 q = camera.invViewProj * vec4(ndc, depth, 1.0);
    vec3 world = q.xyz / q.w;
    vec3 local = (decalSpace.worldToDecal * vec4(world, 1.0)).xyz;
    if (any(greaterThan(abs(local), vec3(0.5))))
        discard;

    vec4 texel = texture(decalTexture, local.xz + 0.5);
    outAlbedo = vec4(texel.rgb * decal.color.rgb, texel.a * decal.color.a);
}
