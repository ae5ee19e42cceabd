// -e NAME restricts the shift to that entry point but keeps the rest of the file: the other
// vertex entry point stays as written, and the report says why it was not shifted.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift -e VSShadow %s -o %t/out.hlsl --report %t/report.json
// RUN: %rmchecks %t/out.hlsl | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// CHECK: float4 VSMain(float3 p : POSITION) : SV_Position
// CHECK-NEXT: {
// CHECK-NEXT: return mul(ViewProj, float4(p, 1.0));
// CHECK: float4 VSShadow(float3 p : POSITION) : SV_Position
// CHECK-NEXT: {
// CHECK-NEXT: return stereoshift_shift_position(mul(LightViewProj, float4(p, 1.0)));
// REPORT: "VSMain": {
// REPORT-NEXT: "found_by": "signature",
// REPORT-NEXT: "note": "not shifted: -e VSShadow names another entry point",
// REPORT-NEXT: "shifted": false,
cbuffer Frame : register(b0) { float4x4 ViewProj; float4x4 LightViewProj; };

float4 VSMain(float3 p : POSITION) : SV_Position
{
    return mul(ViewProj, float4(p, 1.0));
}

float4 VSShadow(float3 p : POSITION) : SV_Position
{
    return mul(LightViewProj, float4(p, 1.0));
}
