#include "lighting.fxh"
float4 main(float4 pos : SV_Position, float3 color : COLOR0) : SV_Target
{
    return float4(ApplyAmbient(color), 1.0f);
}
