// stereoshift-expect: intermediate
// D3D11 PN-triangles hull shader: 3-point triangle patches, screen-size-independent tessellation from camera distance.

cbuffer TessConstants : register(b1)
{
    float3 CameraPos;
    float  MaxTessFactor;
    float  TessDistance;
};

struct HSInput
{
    float3 WorldPos : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct HSOutput
{
    float3 WorldPos : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct PatchConstants
{
    float Edges[3] : SV_TessFactor;
    float Inside   : SV_InsideTessFactor;
};

float EdgeFactor(float3 a, float3 b)
{
    float d = distance((a + b) * 0.5, CameraPos);
    return clamp(MaxTessFactor * TessDistance / max(d, 0.001), 1.0, MaxTessFactor);
}

PatchConstants PatchConstantFunc(InputPatch<HSInput, 3> patch)
{
    PatchConstants pc;
    pc.Edges[0] = EdgeFactor(patch[1].WorldPos, patch[2].WorldPos);
    pc.Edges[1] = EdgeFactor(patch[2].WorldPos, patch[0].WorldPos);
    pc.Edges[2] = EdgeFactor(patch[0].WorldPos, patch[1].WorldPos);
    pc.Inside = (pc.Edges[0] + pc.Edges[1] + pc.Edges[2]) / 3.0;
    return pc;
}

[domain("tri")]
[partitioning("fractional_odd")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("PatchConstantFunc")]
HSOutput HSMain(InputPatch<HSInput, 3> patch, uint id : SV_OutputControlPointID)
{
    HSOutput output;
    output.WorldPos = patch[id].WorldPos;
    output.Normal = patch[id].Normal;
    output.UV = patch[id].UV;
    return output;
}
