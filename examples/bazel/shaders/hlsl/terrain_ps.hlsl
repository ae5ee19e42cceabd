Texture2D Albedo : register(t0);
SamplerState LinearSampler : register(s0);

struct PSInput { float4 position : SV_Position; float2 uv : TEXCOORD0; float fog : TEXCOORD1; };

float4 PSMain(PSInput input) : SV_Target {
    float3 color = Albedo.Sample(LinearSampler, input.uv).rgb;
    return float4(lerp(float3(0.6, 0.7, 0.8), color, input.fog), 1.0);
}
