// Its pixel shader: texture and sampler at bindings 1 and 2 of the same set (one binding space on
// Vulkan, whatever the D3D register class).
[[vk::binding(1, 0)]] Texture2D albedo;
[[vk::binding(2, 0)]] SamplerState linearSampler;

float4 main([[vk::location(0)]] float2 uv : TEXCOORD0) : SV_Target {
  return albedo.Sample(linearSampler, uv);
}
