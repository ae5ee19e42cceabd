#include "common/constants.hlsli"
#include "palette.hlsli"
float4 main(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target { return float4(uv * kBillboardSize, Tint, 1); }
