// stereoshift-expect: fragment
// D3D11 sample-style pixel shader named `*PS.hlsl`: one directional light.
cbuffer Light : register(b0)
{
    float3 LightDirection;
    float Padding;
};

struct PSInput
{
    float4 Position : SV_POSITION;
    float3 Normal : NORMAL;
};

float4 main(PSInput input) : SV_TARGET
{
    float diffuse = saturate(dot(normalize(input.Normal), -LightDirection));
    return float4(diffuse.xxx * 0.8f + 0.2f, 1.0f);
}
