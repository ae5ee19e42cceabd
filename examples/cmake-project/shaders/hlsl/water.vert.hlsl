cbuffer Frame : register(b0) {
  float4x4 viewProj;
  float time;
};

struct VSInput {
  float3 position : POSITION;
  float2 uv : TEXCOORD0;
};

struct VSOutput {
  float4 position : SV_Position;
  float2 uv : TEXCOORD0;
};

VSOutput main(VSInput input) {
  VSOutput output;
  float3 p = input.position;
  p.y += 0.05 * sin(time + p.x * 4.0);
  output.position = mul(viewProj, float4(p, 1.0));
  output.uv = input.uv;
  return output;
}
