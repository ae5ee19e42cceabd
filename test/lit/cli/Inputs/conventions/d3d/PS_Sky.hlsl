Texture2D DiffuseTexture : register(t0);
SamplerState LinearSampler : register(s0);
struct PSInput { float4 Position : SV_POSITION; float2 Tex : TEXCOORD0; };
float4 main(PSInput input) : SV_TARGET
{
    return DiffuseTexture.Sample(LinearSampler, input.Tex);
}
