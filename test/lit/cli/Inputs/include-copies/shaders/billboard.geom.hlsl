#include "common/camera.hlsli"
struct GSIn { float4 center : POSITION; };
struct GSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
[maxvertexcount(4)]
void main(point GSIn input[1], inout TriangleStream<GSOut> stream) {
  const float2 corners[4] = { float2(-1, -1), float2(1, -1), float2(-1, 1), float2(1, 1) };
  for (int i = 0; i < 4; ++i) {
    GSOut o;
    o.pos = mul(ViewProj, input[0].center + float4(corners[i] * kBillboardSize, 0, 0));
    o.uv = corners[i] * 0.5 + 0.5;
    stream.Append(o);
  }
}
