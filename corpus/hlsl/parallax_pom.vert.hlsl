// stereoshift-expect: per-eye-view
// D3D11 parallax-occlusion vertex shader: tangent-space view vector from CameraPosition (shared include) minus the world position.

#include "include/common.hlsli"

struct VSInput
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
    float4 Tangent  : TANGENT;
    float2 UV       : TEXCOORD0;
};

struct VSOutput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
    float3 ViewTS   : TEXCOORD1;
    float3 NormalWS : TEXCOORD2;
};

VSOutput main(VSInput input)
{
    float4 world = mul(World, float4(input.Position, 1.0));
    float3 n = normalize(mul((float3x3)WorldInvTranspose, input.Normal));
    float3 t = normalize(mul((float3x3)World, input.Tangent.xyz));
    float3x3 toTangent = WorldToTangentBasis(n, t, input.Tangent.w);

    VSOutput output;
    output.Position = mul(ViewProj, world);
    output.UV = input.UV;
    output.ViewTS = mul(toTangent, CameraPosition - world.xyz);
    output.NormalWS = n;
    return output;
}
