// stereoshift-expect: fragment
// Stage-named HLSL particle pixel shader: soft round sprite from the quad UV, premultiplied by the particle colour.

float4 main([[vk::location(0)]] float4 inColor : COLOR0, [[vk::location(1)]] float2 inUV : TEXCOORD0) : SV_TARGET
{
    float2 d = inUV * 2.0 - 1.0;
    float alpha = saturate(1.0 - dot(d, d)) * inColor.a;
    return float4(inColor.rgb * alpha, alpha);
}
