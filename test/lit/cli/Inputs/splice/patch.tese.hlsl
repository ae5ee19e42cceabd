// A domain shader for the source-splice tests: the position it returns gets the shift.
cbuffer Frame : register(b0) { float4x4 ViewProj; };
struct CP { float3 pos : POSITION; };
struct PatchConst { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
struct DSOut { float4 pos : SV_Position; };
[domain("tri")]
DSOut DSMain(PatchConst pc, float3 bary : SV_DomainLocation, const OutputPatch<CP, 3> patch)
{
  DSOut o;
  float3 p = patch[0].pos * bary.x + patch[1].pos * bary.y + patch[2].pos * bary.z;
  o.pos = mul(ViewProj, float4(p, 1.0));
  return o;
}
