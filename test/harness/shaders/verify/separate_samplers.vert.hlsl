// Vulkan-style HLSL: textures and samplers declared apart, with [[vk::binding]]; the cube and its
// sampler share one binding (one combined image sampler descriptor).
struct UBO
{
    float4x4 viewProj;
    float4x4 world;
    float displacement;
};
[[vk::binding(0, 0)]] cbuffer ubo : register(b0) { UBO ubo; }
[[vk::binding(1, 0)]] Texture2D heightMap : register(t1);
[[vk::binding(2, 0)]] SamplerState linearSampler : register(s2);
[[vk::binding(3, 0)]] TextureCube skyCube : register(t3);
[[vk::binding(3, 0)]] SamplerState skySampler : register(s3);
[[vk::binding(4, 0)]] Texture2DArray splatLayers : register(t4);

struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
[[vk::location(1)]] float2 UV : TEXCOORD0;
};

struct VSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float3 Sky : COLOR0;
};

VSOutput main(VSInput input)
{
    VSOutput output = (VSOutput)0;
    float h = heightMap.SampleLevel(linearSampler, input.UV, 0.0).r
            + splatLayers.SampleLevel(linearSampler, float3(input.UV, 1.0), 0.0).g;
    output.Sky = skyCube.SampleLevel(skySampler, normalize(input.Pos), 0.0).rgb;
    float4 world = mul(ubo.world, float4(input.Pos + float3(0.0, h * ubo.displacement, 0.0), 1.0));
    output.Pos = mul(ubo.viewProj, world);
    return output;
}
