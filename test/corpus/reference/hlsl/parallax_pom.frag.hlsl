// stereoshift-expect: fragment
// D3D11 parallax-occlusion pixel shader: linear search plus secant refinement along the interpolated tangent-space view vector.

Texture2D    HeightMap     : register(t0);
Texture2D    AlbedoMap     : register(t1);
SamplerState LinearWrap    : register(s0);

cbuffer PomConstants : register(b2)
{
    float3 SunDirection;
    float  HeightScale;
    float  MaxSteps;
};

struct PSInput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
    float3 ViewTS   : TEXCOORD1;
    float3 NormalWS : TEXCOORD2;
};

float4 main(PSInput input) : SV_Target
{
    float3 v = normalize(input.ViewTS);
    float steps = lerp(MaxSteps, 8.0, saturate(v.z));
    float2 delta = -v.xy / max(v.z, 0.05) * HeightScale / steps;
    float layer = 1.0 / steps;

    float2 uv = input.UV;
    float2 dx = ddx(input.UV), dy = ddy(input.UV);
    float rayHeight = 1.0;
    float prevHeight = 1.0, height = HeightMap.SampleGrad(LinearWrap, uv, dx, dy).r;
    [loop] for (int i = 0; i < 64 && height < rayHeight; ++i) {
        prevHeight = height;
        uv += delta;
        rayHeight -= layer;
        height = HeightMap.SampleGrad(LinearWrap, uv, dx, dy).r;
    }
    // Secant step between the last two samples.
    float before = prevHeight - (rayHeight + layer);
    float after = height - rayHeight;
    uv -= delta * saturate(after / (after - before));

    float3 albedo = AlbedoMap.Sample(LinearWrap, uv).rgb;
    float ndl = saturate(dot(normalize(input.NormalWS), -SunDirection));
    return float4(albedo * (0.2 + 0.8 * ndl), 1.0);
}
