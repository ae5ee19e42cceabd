// stereoshift-expect: shift
// Stage-named HLSL geometry shader: expands each point into a camera-facing quad along the camera right/up vectors and projects it.

struct UBO
{
    float4x4 viewProj;
    float4 cameraRight;
    float4 cameraUp;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct GSInput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float4 Color : COLOR0;
[[vk::location(1)]] float Size : TEXCOORD0;
};

struct GSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float4 Color : COLOR0;
[[vk::location(1)]] float2 UV : TEXCOORD0;
};

[maxvertexcount(4)]
void main(point GSInput input[1], inout TriangleStream<GSOutput> outStream)
{
    const float2 corners[4] = { float2(-1, -1), float2(1, -1), float2(-1, 1), float2(1, 1) };
    for (int i = 0; i < 4; i++)
    {
        float3 world = input[0].Pos.xyz + (ubo.cameraRight.xyz * corners[i].x + ubo.cameraUp.xyz * corners[i].y) * input[0].Size;
        GSOutput output = (GSOutput)0;
        output.Pos = mul(ubo.viewProj, float4(world, 1.0));
        output.Color = input[0].Color;
        output.UV = corners[i] * 0.5 + 0.5;
        outStream.Append(output);
    }
    outStream.RestartStrip();
}
