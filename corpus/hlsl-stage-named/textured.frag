// stereoshift-expect: fragment
// Vulkan-sample style HLSL pixel shader in a stage-only .frag file: combined [[vk::binding]] texture and sampler, Lambert term from the interpolated light vector.

[[vk::binding(1, 0)]] Texture2D textureColor : register(t1);
[[vk::binding(1, 0)]] SamplerState samplerColor : register(s1);

struct PSInput
{
[[vk::location(0)]] float2 UV : TEXCOORD0;
[[vk::location(1)]] float3 Normal : NORMAL0;
[[vk::location(2)]] float3 LightVec : TEXCOORD1;
};

float4 main(PSInput input) : SV_TARGET
{
    float4 color = textureColor.Sample(samplerColor, input.UV);
    float3 N = normalize(input.Normal);
    float3 L = normalize(input.LightVec);
    float diffuse = max(dot(N, L), 0.15);
    return float4(color.rgb * diffuse, color.a);
}
