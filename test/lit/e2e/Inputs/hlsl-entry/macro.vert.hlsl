#define VERTEX_ENTRY(name) float4 name(float3 position : POSITION) : SV_Position
cbuffer Camera : register(b0) { float4x4 ViewProj; };
VERTEX_ENTRY(main) { return mul(ViewProj, float4(position, 1.0)); }
