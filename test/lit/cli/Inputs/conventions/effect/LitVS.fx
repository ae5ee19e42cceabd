#include "lighting.fxh"
cbuffer Camera : register(b0) { float4x4 ViewProjection; float4x4 World; };
struct VertexOut { float4 Pos : SV_Position; float3 Color : COLOR0; };
VertexOut main(float3 pos : POSITION, float3 color : COLOR0)
{
    VertexOut o;
    o.Pos = mul(mul(float4(pos, 1.0f), World), ViewProjection);
    o.Color = ApplyAmbient(color);
    return o;
}
