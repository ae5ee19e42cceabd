// -x hlsl (glslc's flag; long form --language) says the input is HLSL whatever its file name says:
// this `.vert` file is parsed as HLSL and converted (the shift injected), and the report says the
// flag decided.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift -x hlsl --verify %s -o %t/out.vert --report %t/report.json
// RUN: %rmchecks %t/out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// RUN: %stereoshift --language hlsl %s -o - | %rmchecks | FileCheck %s
cbuffer Camera : register(b0) { float4x4 ViewProj; };

float4 main(float3 pos : POSITION) : SV_Position
{
  return mul(ViewProj, float4(pos, 1.0));
}
// CHECK: cbuffer Camera : register(b0)
// CHECK: cbuffer StereoParams : register(b1)
// CHECK: eyeSign * separation
// REPORT: "language": "hlsl",
// REPORT-NEXT: "language_reason": "-x hlsl",
// REPORT-NEXT: "language_source": "flag",
