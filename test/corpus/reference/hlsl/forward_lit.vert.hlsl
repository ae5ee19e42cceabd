// stereoshift-expect: shift
// D3D11 forward-lit mesh vertex shader: row-vector mul(v, M) convention with a combined world-view-projection.

cbuffer PerObject : register(b0)
{
    row_major float4x4 WorldViewProj;
    row_major float4x4 WorldMatrix;
    float4 MaterialTint;
};

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float3 WorldNormal : TEXCOORD0;
    float2 UV : TEXCOORD1;
    float4 Tint : COLOR0;
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
    VSOutput output;
    output.Position = mul(float4(input.Position, 1.0), WorldViewProj);
    output.WorldNormal = normalize(mul(input.Normal, (float3x3)WorldMatrix));
    output.UV = input.UV;
    output.Tint = MaterialTint;
    return stereoshift_shift_VSOutput(output);
}
