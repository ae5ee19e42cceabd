// stereoshift-expect: fragment
// D3D11 tonemap pixel shader: Uncharted-2 filmic curve with exposure, vignette and colour grading LUT.

cbuffer TonemapConstants : register(b0)
{
    float Exposure;
    float WhitePoint;
    float VignetteStrength;
    float LutSize;
};

Texture2D    HdrScene     : register(t0);
Texture3D    GradingLut   : register(t1);
SamplerState PointClamp   : register(s0);
SamplerState LinearClamp  : register(s1);

struct PSInput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
};

float3 Uncharted2(float3 x)
{
    const float A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

float4 PSMain(PSInput input) : SV_Target
{
    float3 hdr = HdrScene.Sample(PointClamp, input.UV).rgb * Exposure;
    float3 mapped = Uncharted2(hdr) / Uncharted2(WhitePoint.xxx);
    float2 centred = input.UV - 0.5;
    mapped *= 1.0 - dot(centred, centred) * VignetteStrength;

    float3 lutCoord = saturate(mapped) * ((LutSize - 1.0) / LutSize) + 0.5 / LutSize;
    float3 graded = GradingLut.Sample(LinearClamp, lutCoord).rgb;
    return float4(graded, 1.0);
}
