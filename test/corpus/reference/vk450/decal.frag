#version 450

layout(set = 0, binding = 0, std140) uniform CameraUBO
{
    mat4 viewProj;
    mat4 invViewProj;
} camera;

layout(set = 1, binding = 2, std140) uniform DecalUBO
{
    mat4 worldToDecal;
} decalSpace;

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

layout(set = 1, binding = 0) uniform sampler2D sceneDepth;
layout(set = 1, binding = 1) uniform sampler2D decalTexture;

layout(location = 0) in vec4 inClipPos;
layout(location = 0) out vec4 outAlbedo;

void main()
{
    vec2 ndc = inClipPos.xy / vec2(inClipPos.w);
    vec2 screenUV = (ndc * 0.5) + vec2(0.5);
    float depth = texture(sceneDepth, screenUV).x;
    vec4 _56 = camera.invViewProj * vec4(ndc, depth, 1.0);
    vec4 q = mix(_56, _56 - (camera.invViewProj[0] * ((stereo.eyeSign * stereo.separation) * (1.0 - (stereo.convergence * _56.w)))), bvec4(stereo.eyeSign != 0.0));
    vec3 world = q.xyz / vec3(q.w);
    vec3 local = (decalSpace.worldToDecal * vec4(world, 1.0)).xyz;
    if (any(greaterThan(abs(local), vec3(0.5))))
    {
        discard;
    }
    vec4 texel = texture(decalTexture, local.xz + vec2(0.5));
    outAlbedo = vec4(texel.xyz * decal.color.xyz, texel.w * decal.color.w);
}

