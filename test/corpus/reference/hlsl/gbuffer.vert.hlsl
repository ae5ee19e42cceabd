// stereoshift-expect: shift
// D3D11 G-buffer vertex shader: world-space normal/tangent frame and view depth for the geometry pass.

cbuffer ObjectConstants : register(b0)
{
    float4x4 World;
    float4x4 ViewProj;
    float4x4 View;
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float4 Tangent  : TANGENT;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position  : SV_Position;
    float3 Normal    : TEXCOORD0;
    float3 Tangent   : TEXCOORD1;
    float3 Bitangent : TEXCOORD2;
    float2 UV        : TEXCOORD3;
    float  ViewDepth : TEXCOORD4;
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

VSOutput VSMain(VSInput input)
{
    float4 world = mul(World, float4(input.Position, 1.0));
    VSOutput output;
    output.Position = mul(ViewProj, world);
    output.Normal = normalize(mul((float3x3)World, input.Normal));
    output.Tangent = normalize(mul((float3x3)World, input.Tangent.xyz));
    output.Bitangent = cross(output.Normal, output.Tangent) * input.Tangent.w;
    output.UV = input.UV;
    output.ViewDepth = mul(View, world).z;
    return stereoshift_shift_VSOutput(output);
}
