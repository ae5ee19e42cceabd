// Lit mesh vertex shader, HLSL in a stage-named file.
struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
[[vk::location(1)]] float3 Normal : NORMAL0;
};

struct UBO
{
  float4x4 viewProj;
  float4x4 model;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct VSOutput
{
  float4 Pos : SV_POSITION;
[[vk::location(0)]] float3 Normal : NORMAL0;
};

VSOutput main(VSInput input)
{
  VSOutput output = (VSOutput)0;
  output.Normal = mul((float3x3)ubo.model, input.Normal);
  output.Pos = mul(ubo.viewProj, mul(ubo.model, float4(input.Pos, 1.0)));
  return output;
}
