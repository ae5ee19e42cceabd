// stereoshift-expect: shift
// D3D11 skybox vertex shader: camera-centred cube, output position .xyww so the sky sits on the far plane.

cbuffer SkyConstants : register(b0)
{
    float4x4 ViewRotationProj;   // projection * view with the translation removed
    float4   SkyTint;
};

struct VSInput
{
    float3 Position : POSITION;
};

struct VSOutput
{
    float4 Position  : SV_Position;
    float3 Direction : TEXCOORD0;
    float4 Tint      : COLOR0;
};

VSOutput VSMain(VSInput input)
{
    VSOutput output;
    float4 pos = mul(ViewRotationProj, float4(input.Position, 1.0));
    output.Position = pos.xyww;
    output.Direction = input.Position;
    output.Tint = SkyTint;
    return output;
}
