// A Vulkan-style HLSL vertex shader: its cbuffer is at binding 0 of set 0.
struct Camera { float4x4 viewProj; };
[[vk::binding(0, 0)]] ConstantBuffer<Camera> camera;

struct VSOut { float4 pos : SV_Position; [[vk::location(0)]] float2 uv : TEXCOORD0; };

VSOut main([[vk::location(0)]] float3 position : POSITION, [[vk::location(1)]] float2 uv : TEXCOORD0) {
  VSOut o;
  o.pos = mul(camera.viewProj, float4(position, 1.0));
  o.uv = uv;
  return o;
}
