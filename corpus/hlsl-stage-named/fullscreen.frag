// stereoshift-expect: fragment
// Stage-named HLSL post-process pixel shader: vignette and gamma over the scene colour sampled at the full-screen UV.

[[vk::binding(0, 0)]] Texture2D sceneColor : register(t0);
[[vk::binding(0, 0)]] SamplerState sceneSampler : register(s0);

float4 main([[vk::location(0)]] float2 inUV : TEXCOORD0) : SV_TARGET
{
    float3 color = sceneColor.Sample(sceneSampler, inUV).rgb;
    float2 centred = inUV - 0.5;
    float vignette = saturate(1.0 - dot(centred, centred) * 1.5);
    return float4(pow(abs(color * vignette), 1.0 / 2.2), 1.0);
}
