// stereoshift-expect: shift
// Main and shadow vertex shaders plus the PS of the main pass in one file: each VS is classified on its own.
cbuffer Frame : register(b0)
{
    float4x4 ViewProj;
    float4x4 LightViewProj;
};

cbuffer Object : register(b1)
{
    float4x4 World;
};

struct SceneOut
{
    float4 Pos : SV_Position;
    float4 LightPos : TEXCOORD0;
};

SceneOut VSMain(float3 pos : POSITION)
{
    SceneOut o;
    float4 world = mul(World, float4(pos, 1.0));
    o.Pos = mul(ViewProj, world);
    o.LightPos = mul(LightViewProj, world);
    return o;
}

float4 VSShadow(float3 pos : POSITION) : SV_Position
{
    return mul(LightViewProj, mul(World, float4(pos, 1.0)));
}

float4 PSMain(SceneOut i) : SV_Target
{
    float depth = i.LightPos.z / i.LightPos.w;
    return float4(depth.xxx, 1.0);
}
