// An HLSL SM5 domain shader (tessellation evaluation) comes back as HLSL: same entry point, domain
// and semantics, and the position it returns gets the guarded shift.
// RUN: %stereoshift --verify %s -o %t.out.hlsl
// RUN: %rmchecks %t.out.hlsl | FileCheck %s
// RUN: glslangValidator -D -V -S tese -e DSMain -o %t.spv %t.out.hlsl
cbuffer Frame : register(b0) { float4x4 ViewProj; };
// CHECK: cbuffer Frame : register(b0)
struct CP { float3 pos : POSITION; };
struct PatchConst { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
struct DSOut { float4 pos : SV_Position; };
// CHECK: struct DSOut { float4 pos : SV_Position; };
// CHECK: cbuffer StereoParams : register(b1)
// CHECK: abs({{.*}}.w - 1.0f) > {{9\.9999997[0-9]*e-0*6}}f
// CHECK: eyeSign * separation
[domain("tri")]
DSOut DSMain(PatchConst pc, float3 bary : SV_DomainLocation, const OutputPatch<CP, 3> patch)
{
  DSOut o;
  float3 p = patch[0].pos * bary.x + patch[1].pos * bary.y + patch[2].pos * bary.z;
  o.pos = mul(ViewProj, float4(p, 1.0));
  return o;
}
// CHECK: {{^}}[domain("tri")]
// CHECK-NEXT: DSOut DSMain(PatchConst pc, float3 bary : SV_DomainLocation, const OutputPatch<CP, 3> patch)
// CHECK-NEXT: {
// CHECK-NEXT: return {{[A-Za-z_]*shift[A-Za-z_]*}}(
