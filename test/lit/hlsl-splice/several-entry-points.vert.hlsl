// A file with two vertex entry points and a pixel shader comes back as one file with all three:
// each vertex entry point classified by its own compile and shifted at its return, the pixel
// shader as written; the report lists every entry point. Each shifted entry re-compiles.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift %s -o %t/out.hlsl --report %t/report.json
// RUN: %rmchecks %t/out.hlsl | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// RUN: glslangValidator -D -V -S vert -e mainVS -o %t/a.spv %t/out.hlsl
// RUN: glslangValidator -D -V -S vert -e skyVS -o %t/b.spv %t/out.hlsl
// RUN: glslangValidator -D -V -S frag -e mainPS -o %t/c.spv %t/out.hlsl
// CHECK: float4 mainVS(float3 p : POSITION) : SV_Position
// CHECK-NEXT: {
// CHECK-NEXT: return stereoshift_shift_position(mul(ViewProj, float4(p, 1.0)));
// CHECK: float4 skyVS(float3 p : POSITION) : SV_Position
// CHECK-NEXT: {
// CHECK-NEXT: return stereoshift_shift_position(mul(SkyViewProj, float4(p, 1.0)).xyww);
// CHECK: float4 mainPS(float4 pos : SV_Position) : SV_Target
// CHECK-NEXT: {
// CHECK-NEXT: return float4(1.0, 0.5, 0.25, 1.0);
// REPORT: "entry_points": {
// REPORT-NEXT: "mainPS": {
// REPORT-NEXT: "found_by": "signature",
// REPORT-NEXT: "shifted": false,
// REPORT-NEXT: "stage": "frag"
// REPORT: "mainVS": {
// REPORT-NEXT: "classification": "perspective",
// REPORT-NEXT: "shifted": true,
// REPORT: "skyVS": {
// REPORT-NEXT: "classification": "perspective",
// REPORT-NEXT: "found_by": "signature",
// REPORT-NEXT: "shifted": true,
// REPORT: "route": "hlsl-source-splice",
cbuffer Frame : register(b0) { float4x4 ViewProj; float4x4 SkyViewProj; };

float4 mainVS(float3 p : POSITION) : SV_Position
{
    return mul(ViewProj, float4(p, 1.0));
}

float4 skyVS(float3 p : POSITION) : SV_Position
{
    return mul(SkyViewProj, float4(p, 1.0)).xyww;
}

float4 mainPS(float4 pos : SV_Position) : SV_Target
{
    return float4(1.0, 0.5, 0.25, 1.0);
}
