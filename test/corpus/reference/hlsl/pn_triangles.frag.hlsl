// stereoshift-expect: fragment
// D3D11 PN-triangles pixel shader: smooth-shaded surface with a matcap lookup from the view-space normal.

cbuffer MatcapConstants : register(b3)
{
    float4x4 ViewRotation;
    float4   BaseColor;
};

Texture2D    MatcapTexture : register(t0);
Texture2D    DetailTexture : register(t1);
SamplerState ClampSampler  : register(s0);

struct PSInput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

float4 PSMain(PSInput input) : SV_Target
{
    float3 viewNormal = normalize(mul((float3x3)ViewRotation, normalize(input.Normal)));
    float2 matcapUV = viewNormal.xy * float2(0.5, -0.5) + 0.5;
    float3 matcap = MatcapTexture.Sample(ClampSampler, matcapUV).rgb;
    float3 detail = DetailTexture.Sample(ClampSampler, input.UV).rgb;
    return float4(matcap * detail * BaseColor.rgb, BaseColor.a);
}
