// stereoshift-expect: fragment
// D3D11 skybox pixel shader: cube-map sky blended toward a procedural gradient below the horizon.

TextureCube  SkyCube    : register(t0);
SamplerState SkySampler : register(s0);

cbuffer GradientConstants : register(b1)
{
    float3 GroundColor;
    float  GroundBlend;
};

struct PSInput
{
    float4 Position  : SV_Position;
    float3 Direction : TEXCOORD0;
    float4 Tint      : COLOR0;
};

float4 PSMain(PSInput input) : SV_Target
{
    float3 dir = normalize(input.Direction);
    float3 sky = SkyCube.Sample(SkySampler, dir).rgb * input.Tint.rgb;
    float below = saturate(-dir.y * GroundBlend);
    return float4(lerp(sky, GroundColor, below), 1.0);
}
