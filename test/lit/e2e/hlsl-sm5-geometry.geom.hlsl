// An HLSL SM5 geometry shader comes back as HLSL: its cbuffer and register, its entry point and
// signature, and every vertex it appends gets the guarded shift first.
// RUN: %stereoshift --verify %s -o %t.out.hlsl --report %t.json
// RUN: %rmchecks %t.out.hlsl | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -D -V -S geom -e GSMain -o %t.spv %t.out.hlsl
cbuffer Frame : register(b0) { float4x4 ViewProj; };
// CHECK: cbuffer Frame : register(b0)
// CHECK: cbuffer StereoParams : register(b1)
// CHECK: abs({{.*}}.w - 1.0f) > {{9\.9999997[0-9]*e-0*6}}f
// CHECK: eyeSign * separation
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
// CHECK: {{^}}[maxvertexcount(3)]
// CHECK-NEXT: void GSMain(triangle GSIn input[3], inout TriangleStream<GSOut> stream)
// CHECK: stream.Append({{[A-Za-z_]*shift[A-Za-z_]*}}(o));
// CHECK: stream.RestartStrip();
// REPORT: "sites": 1
