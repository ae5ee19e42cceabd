// stereoshift-expect: shift
// SM 6 / Vulkan style: ConstantBuffer<T> with [[vk::binding]], [[vk::location]] outputs, VS and PS in one file.
struct SceneData
{
    float4x4 viewProjection;
    float4x4 model;
};

[[vk::binding(0, 0)]] ConstantBuffer<SceneData> scene : register(b0, space0);
[[vk::binding(1, 0)]] Texture2D albedo : register(t1, space0);
[[vk::binding(2, 0)]] SamplerState albedoSampler : register(s2, space0);

struct VSInput
{
    [[vk::location(0)]] float3 position : POSITION;
    [[vk::location(1)]] float2 uv : TEXCOORD0;
};

struct VSOutput
{
    float4 position : SV_Position;
    [[vk::location(0)]] float2 uv : TEXCOORD0;
};

VSOutput vsMain(VSInput input)
{
    VSOutput output;
    float4 world = mul(scene.model, float4(input.position, 1.0));
    output.position = mul(scene.viewProjection, world);
    output.uv = input.uv;
    return output;
}

float4 psMain(VSOutput input) : SV_Target
{
    return albedo.Sample(albedoSampler, input.uv);
}
