// An HLSL pixel shader in a `.frag` file: detected as HLSL by its content (Texture2D, SamplerState,
// [[vk::binding]], `: SV_TARGET`), nothing per-eye in it, so it comes back byte for byte.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift %s -o %t/out.frag --report %t/report.json
// RUN: cmp %s %t/out.frag
// RUN: FileCheck %s --input-file %t/report.json
[[vk::binding(1, 0)]] Texture2D textureColor : register(t1);
[[vk::binding(1, 0)]] SamplerState samplerColor : register(s1);

float4 main([[vk::location(0)]] float2 inUV : TEXCOORD0) : SV_TARGET
{
  return textureColor.Sample(samplerColor, inUV);
}
// CHECK: "classification": "no-position-stage",
// CHECK: "language": "hlsl",
// CHECK-NEXT: "language_reason": "no #version; HLSL constructs: {{\[\[}}vk::binding]], Texture2D, : register(, SamplerState, ... (HLSL {{[0-9]+}}, GLSL 0)",
// CHECK-NEXT: "language_source": "content",
// CHECK-NEXT: "ok": true,
// CHECK-NEXT: "output": "copied",
