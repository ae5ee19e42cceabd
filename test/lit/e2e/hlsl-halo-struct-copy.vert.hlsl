// A copy of SV_Position made through the HLSL output struct moves with the shift (halo), while an
// output that is not a copy stays as it is.
// RUN: %stereoshift --verify %s -o %t.hlsl --report - | FileCheck %s --check-prefix=REPORT
// RUN: %stereoshift --no-halo %s -o %t.nohalo.hlsl --report - | FileCheck %s --check-prefix=NOHALO
cbuffer Frame : register(b0) { float4x4 ViewProj; };
struct VSOut {
  float4 Position : SV_Position;
  float4 ClipPos  : TEXCOORD0;
  float4 Color    : COLOR0;
};
VSOut VSMain(float3 pos : POSITION)
{
  VSOut o;
  o.Position = mul(ViewProj, float4(pos, 1.0));
  o.ClipPos = o.Position;
  o.Color = float4(pos, 1.0);
  return o;
}
// REPORT: "shifted_outputs": [
// REPORT-NEXT: "@entryPointOutput.ClipPos"
// REPORT-NEXT: ]
// NOHALO: "classification": "perspective"
// NOHALO-NOT: shifted_outputs
