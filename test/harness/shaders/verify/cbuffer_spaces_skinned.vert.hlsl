// D3D12-style HLSL skinning: constants in register spaces (per frame b0 space0, per object b1,
// bones b0 space1), a vertex-fetched detail texture t0 with sampler s0, bone indices as uint4.
cbuffer PerFrame : register(b0)
{
    float4x4 ViewProjection;
    float4 CameraPosition;
};

cbuffer PerObject : register(b1)
{
    float4x4 World;
};

cbuffer Bones : register(b0, space1)
{
    float4x4 BoneTransforms[16];
};

Texture2D DetailMap : register(t0);
SamplerState LinearWrap : register(s0);

struct VertexInput
{
    float3 Position : POSITION;
    float3 Normal : NORMAL;
    float2 TexCoord : TEXCOORD0;
    uint4 BoneIndices : BLENDINDICES;
    float4 BoneWeights : BLENDWEIGHT;
};

struct VertexOutput
{
    float4 Position : SV_Position;
    float3 NormalW : NORMAL;
    float2 TexCoord : TEXCOORD0;
    float Detail : TEXCOORD1;
};

VertexOutput main(VertexInput input)
{
    float4x4 skin = BoneTransforms[input.BoneIndices.x % 16] * input.BoneWeights.x +
                    BoneTransforms[input.BoneIndices.y % 16] * input.BoneWeights.y +
                    BoneTransforms[input.BoneIndices.z % 16] * input.BoneWeights.z +
                    BoneTransforms[input.BoneIndices.w % 16] * input.BoneWeights.w;
    float4 posW = mul(World, mul(skin, float4(input.Position, 1.0f)));
    VertexOutput output;
    output.Position = mul(ViewProjection, posW);
    output.NormalW = mul((float3x3)World, input.Normal);
    output.TexCoord = input.TexCoord;
    output.Detail = DetailMap.SampleLevel(LinearWrap, input.TexCoord, 0).r;
    return output;
}
