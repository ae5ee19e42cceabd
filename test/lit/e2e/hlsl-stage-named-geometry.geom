// An HLSL geometry shader in a `.geom` file: detected as HLSL by its content ([maxvertexcount],
// TriangleStream, [[vk::location]], semantics) and taken through the HLSL source splice, so every
// appended vertex gets the guarded shift; the output is HLSL that still compiles.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift --verify %s -o %t/out.geom --report %t/report.json
// RUN: %rmchecks %t/out.geom | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// RUN: glslangValidator -D -V -S geom -e main -o %t/out.spv %t/out.geom
struct UBO { float4x4 viewProj; };
[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct GSInput
{
  float4 Pos : SV_POSITION;
[[vk::location(0)]] float3 Normal : NORMAL0;
};

struct GSOutput
{
  float4 Pos : SV_POSITION;
[[vk::location(0)]] float3 Color : COLOR0;
};

[maxvertexcount(6)]
void main(triangle GSInput input[3], inout LineStream<GSOutput> outStream)
{
  for (int i = 0; i < 3; i++)
  {
    GSOutput a = (GSOutput)0, b = (GSOutput)0;
    a.Pos = mul(ubo.viewProj, input[i].Pos);
    a.Color = float3(1.0, 0.0, 0.0);
    outStream.Append(a);
    b.Pos = mul(ubo.viewProj, float4(input[i].Pos.xyz + input[i].Normal * 0.1, 1.0));
    b.Color = float3(0.0, 0.0, 1.0);
    outStream.Append(b);
    outStream.RestartStrip();
  }
}
// CHECK: cbuffer ubo : register(b0)
// CHECK: cbuffer StereoParams : register(b1)
// CHECK: abs({{.*}}.Pos.w - 1.0f) >
// CHECK: eyeSign * separation
// CHECK: outStream.Append(stereoshift_shift_GSOutput(a));
// CHECK: outStream.Append(stereoshift_shift_GSOutput(b));
// REPORT: "language": "hlsl",
// REPORT-NEXT: "language_reason": "no #version; HLSL constructs: float4x4, {{\[\[}}vk::binding]], cbuffer, : register(, ... (HLSL {{[0-9]+}}, GLSL 0)",
// REPORT-NEXT: "language_source": "content",
// REPORT: "sites": 2
// REPORT: "route": "hlsl-source-splice",
