// stereoshift-expect: shift
// D3D11 instanced foliage vertex shader: per-instance transforms from a structured buffer indexed by SV_InstanceID, with wind sway.

cbuffer SceneConstants : register(b0)
{
    float4x4 ViewProj;
    float3   WindDirection;
    float    Time;
};

struct InstanceData
{
    float4x4 World;
    float4   TintAndPhase;   // rgb tint, a wind phase
};

StructuredBuffer<InstanceData> Instances : register(t0);

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
    float4 Color    : COLOR0;      // r = sway weight
    uint InstanceId : SV_InstanceID;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
    float3 Tint     : COLOR0;
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
    InstanceData inst = Instances[input.InstanceId];
    float4 world = mul(inst.World, float4(input.Position, 1.0));
    float sway = sin(Time * 1.7 + inst.TintAndPhase.a) * input.Color.r;
    world.xyz += WindDirection * sway * 0.15;

    VSOutput output;
    output.Position = mul(ViewProj, world);
    output.Normal = normalize(mul((float3x3)inst.World, input.Normal));
    output.UV = input.UV;
    output.Tint = inst.TintAndPhase.rgb;
    return stereoshift_shift_VSOutput(output);
}
