// stereoshift-expect: shift
// Vertex outputs as out parameters (no struct), an early return for culled instances, and the PS beside it.
cbuffer PerFrame : register(b0)
{
    float4x4 gViewProj;
};

cbuffer PerInstance : register(b1)
{
    float4x4 gWorld;
    float gVisible;
};

void VSMain(in float3 iPos : POSITION, in float2 iUV : TEXCOORD0,
            out float4 oPos : SV_Position, out float2 oUV : TEXCOORD0)
{
    oUV = iUV;
    oPos = mul(gViewProj, mul(gWorld, float4(iPos, 1.0)));
    if (gVisible == 0.0)
    {
        oPos = float4(0.0, 0.0, -2.0, 1.0);
        return;
    }
}

float4 PSMain(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    return float4(uv, 0.0, 1.0);
}
