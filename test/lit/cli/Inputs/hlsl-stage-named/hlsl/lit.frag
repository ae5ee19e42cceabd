// Lit mesh pixel shader, HLSL in a stage-named file.
[[vk::binding(1, 0)]]
cbuffer light : register(b1) { float4 lightDir; float4 albedo; }

float4 main([[vk::location(0)]] float3 inNormal : NORMAL0) : SV_TARGET
{
  float diffuse = saturate(dot(normalize(inNormal), -lightDir.xyz));
  return float4(albedo.rgb * (0.1 + diffuse), 1.0);
}
