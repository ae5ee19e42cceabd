// stereoshift-expect: shift
// D3D12 sample style: PSInput shared by VSMain and PSMain, a scene constant buffer with one matrix.
cbuffer SceneConstantBuffer : register(b0)
{
    float4x4 worldViewProj;
    float4 tint;
};

struct PSInput
{
    float4 position : SV_POSITION;
    float4 color : COLOR;
};

PSInput VSMain(float4 position : POSITION, float4 color : COLOR)
{
    PSInput result;

    result.position = mul(position, worldViewProj);
    result.color = color * tint;

    return result;
}

float4 PSMain(PSInput input) : SV_TARGET
{
    return input.color;
}
