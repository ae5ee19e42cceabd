// stereoshift-expect: shift
// D3D11 sample-style vertex shader named `*VS.hlsl`: four-bone skinning, then the view-projection.
cbuffer PerFrame : register(b0)
{
    float4x4 ViewProjection;
};
cbuffer Bones : register(b1)
{
    float4x4 BoneMatrices[64];
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal : NORMAL;
    uint4 BoneIndices : BLENDINDICES;
    float4 BoneWeights : BLENDWEIGHT;
};

struct VSOutput
{
    float4 Position : SV_POSITION;
    float3 Normal : NORMAL;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};

VSOutput stereoshift_shift_VSOutput(VSOutput stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Position.w))
    {
        precise float stereoshift_x = stereoshift_v.Position.x + (eyeSign * separation) * (stereoshift_v.Position.w - convergence);
        stereoshift_v.Position.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VSOutput main(VSInput input)
{
    float4x4 skin = BoneMatrices[input.BoneIndices.x] * input.BoneWeights.x +
                    BoneMatrices[input.BoneIndices.y] * input.BoneWeights.y +
                    BoneMatrices[input.BoneIndices.z] * input.BoneWeights.z +
                    BoneMatrices[input.BoneIndices.w] * input.BoneWeights.w;
    VSOutput output;
    float4 world = mul(float4(input.Position, 1.0f), skin);
    output.Position = mul(world, ViewProjection);
    output.Normal = mul(input.Normal, (float3x3)skin);
    return stereoshift_shift_VSOutput(output);
}
