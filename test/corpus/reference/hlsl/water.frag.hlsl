// stereoshift-expect: fragment
// D3D11 water pixel shader: refracts the opaque scene at distorted screen UVs and fades by scene depth difference.

cbuffer WaterShading : register(b1)
{
    float3 ShallowColor;
    float  Distortion;
    float3 DeepColor;
    float  DepthFade;
};

Texture2D    SceneColor   : register(t0);
Texture2D    SceneDepth   : register(t1);
Texture2D    NormalMap    : register(t2);
SamplerState LinearClamp  : register(s0);
SamplerState LinearWrap   : register(s1);

struct PSInput
{
    float4 Position : SV_Position;
    float4 ClipPos  : TEXCOORD0;
    float2 ScreenUV : TEXCOORD1;
    float2 UV0      : TEXCOORD2;
    float2 UV1      : TEXCOORD3;
};

float4 main(PSInput input) : SV_Target
{
    float3 n = NormalMap.Sample(LinearWrap, input.UV0).xyz + NormalMap.Sample(LinearWrap, input.UV1).xyz - 1.0;
    float2 uv = input.ScreenUV + n.xy * Distortion;
    float sceneDepth = SceneDepth.Sample(LinearClamp, uv).r;
    float waterDepth = input.ClipPos.z / input.ClipPos.w;
    float thickness = saturate((sceneDepth - waterDepth) * DepthFade);
    float3 refracted = SceneColor.Sample(LinearClamp, uv).rgb;
    float3 tint = lerp(ShallowColor, DeepColor, thickness);
    return float4(refracted * tint, 1.0);
}
