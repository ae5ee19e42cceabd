// HLSL kept in a file named by stage only (`.vert`, no `.hlsl`), Vulkan-sample style with
// [[vk::binding]] and [[vk::location]]: detected as HLSL by its content, converted as HLSL (the
// shift injected), written under the input's own name, and the report says how it was decided.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift --verify %s -o %t/out.vert --report %t/report.json
// RUN: %rmchecks %t/out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// RUN: glslangValidator -D -V -S vert -e main -o %t/out.spv %t/out.vert
struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
[[vk::location(1)]] float2 UV : TEXCOORD0;
};

struct UBO
{
  float4x4 viewProj;
  float4x4 model;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

struct VSOutput
{
  float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
};

VSOutput main(VSInput input)
{
  VSOutput output = (VSOutput)0;
  output.UV = input.UV;
  output.Pos = mul(ubo.viewProj, mul(ubo.model, float4(input.Pos, 1.0)));
  return output;
}
// CHECK: cbuffer ubo : register(b0)
// CHECK: struct VSOutput
// CHECK-NEXT: {
// CHECK-NEXT: float4 Pos : SV_POSITION;
// CHECK-NEXT: {{\[\[}}vk::location(0)]] float2 UV : TEXCOORD0;
// CHECK: cbuffer StereoParams : register(b1)
// CHECK: if (eyeSign != 0.0f && abs(stereoshift_v.Pos.w - 1.0f) >
// CHECK: eyeSign * separation
// CHECK: VSOutput main(VSInput input)
// CHECK: return stereoshift_shift_VSOutput(output);
// REPORT: "classification": "perspective",
// REPORT: "language": "hlsl",
// REPORT-NEXT: "language_reason": "no #version; HLSL constructs: {{\[\[}}vk::location]], float3, : POSITION0, float2, ... (HLSL {{[0-9]+}}, GLSL 0)",
// REPORT-NEXT: "language_source": "content",
// REPORT: "output_file": "{{.*}}out.vert",
// REPORT: "target": "hlsl",
