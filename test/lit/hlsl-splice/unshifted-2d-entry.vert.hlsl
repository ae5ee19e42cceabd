// A second vertex entry point whose clip w is 1 (a full-screen pass) is classified by its own
// compile as 2D and gets no shift, while the perspective one beside it does.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift %s -o %t/out.hlsl --report %t/report.json
// RUN: %rmchecks %t/out.hlsl | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// CHECK: return stereoshift_shift_position(mul(ViewProj, float4(p, 1.0)));
// CHECK: float4 FullscreenVS(uint id : SV_VertexID) : SV_Position
// CHECK-NEXT: {
// CHECK-NEXT: float2 uv = float2((id << 1) & 2, id & 2);
// CHECK-NEXT: return float4(uv * 2.0 - 1.0, 0.0, 1.0);
// REPORT: "FullscreenVS": {
// REPORT-NEXT: "classification": "2d-constant-w",
// REPORT-NEXT: "found_by": "signature",
// REPORT-NEXT: "shifted": false,
cbuffer Frame : register(b0) { float4x4 ViewProj; };

float4 VSMain(float3 p : POSITION) : SV_Position
{
    return mul(ViewProj, float4(p, 1.0));
}

float4 FullscreenVS(uint id : SV_VertexID) : SV_Position
{
    float2 uv = float2((id << 1) & 2, id & 2);
    return float4(uv * 2.0 - 1.0, 0.0, 1.0);
}
