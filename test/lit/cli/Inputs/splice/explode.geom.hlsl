// A geometry shader for the source-splice tests: every appended vertex gets the shift.
cbuffer Frame : register(b0) { float4x4 ViewProj; };
struct GSIn { float3 pos : POSITION; };
struct GSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
[maxvertexcount(3)]
void GSMain(triangle GSIn input[3], inout TriangleStream<GSOut> stream)
{
  for (int i = 0; i < 3; ++i) {
    GSOut o;
    o.pos = mul(ViewProj, float4(input[i].pos, 1.0));
    o.uv = float2(i, 0);
    stream.Append(o);
  }
  stream.RestartStrip();
}
