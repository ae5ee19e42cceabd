// stereoshift-expect: shift
// D3D11 deferred point-light volume vertex shader: scales a unit sphere to the light radius and projects it.

cbuffer LightVolumeConstants : register(b0)
{
    float4x4 ViewProj;
    float3   LightPosition;
    float    LightRadius;
};

struct VSInput
{
    float3 Position : POSITION;   // unit icosphere
};

struct VSOutput
{
    float4 Position : SV_Position;
};

VSOutput VSMain(VSInput input)
{
    // Inflate slightly so the low-poly sphere fully covers the true radius.
    float3 world = LightPosition + input.Position * LightRadius * 1.08;
    VSOutput output;
    output.Position = mul(ViewProj, float4(world, 1.0));
    return output;
}
