// A geometry shader that also hands its clip position on in a TEXCOORD: the halo pass would shift
// that copy too, which the source splice cannot.
cbuffer Frame : register(b0) { float4x4 ViewProj; };
struct GSIn { float3 pos : POSITION; };
struct GSOut { float4 pos : SV_Position; float4 clip : TEXCOORD0; };
[maxvertexcount(3)]
void GSMain(triangle GSIn input[3], inout TriangleStream<GSOut> stream)
{
  for (int i = 0; i < 3; ++i) {
    GSOut o;
    o.pos = mul(ViewProj, float4(input[i].pos, 1.0));
    o.clip = o.pos;
    stream.Append(o);
  }
}
