// stereoshift-expect: intermediate
// Stage-named HLSL hull shader: 3-point triangle patches with tessellation factors from the camera distance of each edge.

struct UBO
{
    float4 cameraPos;
    float tessFactor;
    float tessDistance;
    float2 padding;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct VSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
};

struct HSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
};

struct ConstantsHSOutput
{
    float TessLevelOuter[3] : SV_TessFactor;
    float TessLevelInner : SV_InsideTessFactor;
};

float edgeFactor(float3 a, float3 b)
{
    float d = distance((a + b) * 0.5, ubo.cameraPos.xyz);
    return clamp(ubo.tessFactor * ubo.tessDistance / max(d, 0.001), 1.0, 64.0);
}

ConstantsHSOutput ConstantsHS(InputPatch<VSOutput, 3> patch)
{
    ConstantsHSOutput output = (ConstantsHSOutput)0;
    output.TessLevelOuter[0] = edgeFactor(patch[1].Pos.xyz, patch[2].Pos.xyz);
    output.TessLevelOuter[1] = edgeFactor(patch[2].Pos.xyz, patch[0].Pos.xyz);
    output.TessLevelOuter[2] = edgeFactor(patch[0].Pos.xyz, patch[1].Pos.xyz);
    output.TessLevelInner = (output.TessLevelOuter[0] + output.TessLevelOuter[1] + output.TessLevelOuter[2]) / 3.0;
    return output;
}

[domain("tri")]
[partitioning("fractional_odd")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("ConstantsHS")]
[maxtessfactor(64.0f)]
HSOutput main(InputPatch<VSOutput, 3> patch, uint InvocationID : SV_OutputControlPointID)
{
    HSOutput output = (HSOutput)0;
    output.Pos = patch[InvocationID].Pos;
    output.UV = patch[InvocationID].UV;
    return output;
}
