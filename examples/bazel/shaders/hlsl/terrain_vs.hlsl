#include "scene_limits.h"

cbuffer Frame : register(b0) {
    float4x4 ViewProjection;
    float3 EyePosition;
};

struct VSInput { float3 position : POSITION; float2 uv : TEXCOORD0; };
struct VSOutput { float4 position : SV_Position; float2 uv : TEXCOORD0; float fog : TEXCOORD1; };

VSOutput VSMain(VSInput input) {
    VSOutput output;
    output.position = mul(ViewProjection, float4(input.position, 1.0));
    output.uv = input.uv;
    output.fog = exp(-FOG_DENSITY * distance(input.position, EyePosition));
    return output;
}
