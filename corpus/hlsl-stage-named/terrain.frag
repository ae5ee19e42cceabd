// stereoshift-expect: fragment
// Stage-named HLSL terrain pixel shader: blends grass and rock colours by the displaced height.

float4 main([[vk::location(0)]] float2 inUV : TEXCOORD0, [[vk::location(1)]] float inHeight : TEXCOORD1) : SV_TARGET
{
    float3 grass = float3(0.24, 0.42, 0.16);
    float3 rock = float3(0.45, 0.42, 0.38);
    float3 color = lerp(grass, rock, smoothstep(0.35, 0.7, inHeight));
    float stripes = 0.9 + 0.1 * frac(inUV.x * 64.0);
    return float4(color * stripes, 1.0);
}
