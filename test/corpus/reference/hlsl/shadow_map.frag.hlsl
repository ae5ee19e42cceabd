// stereoshift-expect: fragment
// D3D11 shadow-map pixel shader: writes linearised depth moments for variance shadow mapping.

cbuffer ShadowPixelConstants : register(b1)
{
    float LightNear;
    float LightFar;
    float AlphaCutoff;
    float Padding;
};

Texture2D    AlphaTexture : register(t0);
SamplerState PointSampler : register(s0);

struct PSInput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
};

float2 main(PSInput input) : SV_Target
{
    clip(AlphaTexture.Sample(PointSampler, input.UV).a - AlphaCutoff);
    float z = input.Position.z;
    float linearDepth = LightNear * LightFar / (LightFar - z * (LightFar - LightNear));
    float d = (linearDepth - LightNear) / (LightFar - LightNear);
    return float2(d, d * d);
}
