// stereoshift-expect: shift
// D3D11 skinned-mesh vertex shader: four-influence skinning from a bone palette in a constant buffer.

#define MAX_BONES 96

cbuffer SkinningConstants : register(b0)
{
    float4x4 BonePalette[MAX_BONES];
};

cbuffer CameraConstants : register(b1)
{
    float4x4 View;
    float4x4 Projection;
};

struct VSInput
{
    float3 Position    : POSITION;
    float3 Normal      : NORMAL;
    float2 UV          : TEXCOORD0;
    uint4  BoneIndices : BLENDINDICES;
    float4 BoneWeights : BLENDWEIGHT;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b3)
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
    float4x4 skin = BonePalette[input.BoneIndices.x] * input.BoneWeights.x
                  + BonePalette[input.BoneIndices.y] * input.BoneWeights.y
                  + BonePalette[input.BoneIndices.z] * input.BoneWeights.z
                  + BonePalette[input.BoneIndices.w] * input.BoneWeights.w;

    float4 world = mul(skin, float4(input.Position, 1.0));
    VSOutput output;
    output.Normal = normalize(mul((float3x3)skin, input.Normal));
    output.UV = input.UV;
    output.Position = mul(Projection, mul(View, world));
    return stereoshift_shift_VSOutput(output);
}
