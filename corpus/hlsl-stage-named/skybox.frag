// stereoshift-expect: fragment
// Stage-named HLSL skybox pixel shader: cube-map lookup with an exposure factor from a push-constant block.

[[vk::binding(1, 0)]] TextureCube textureCubeMap : register(t1);
[[vk::binding(1, 0)]] SamplerState samplerCubeMap : register(s1);

struct PushConsts
{
    float exposure;
};
[[vk::push_constant]] PushConsts pushConsts;

float4 main([[vk::location(0)]] float3 inUVW : TEXCOORD0) : SV_TARGET
{
    float3 hdr = textureCubeMap.Sample(samplerCubeMap, inUVW).rgb;
    float3 mapped = 1.0 - exp(-hdr * pushConsts.exposure);
    return float4(mapped, 1.0);
}
