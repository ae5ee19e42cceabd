// What the text cannot carry (here the eye parameters as push constants: the splice declares a
// cbuffer only) leaves a vertex shader to SPIRV-Cross's re-emit, and a note on stderr and in the
// report says why and what that costs: never silently.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift --eye-source push-constant %s -o %t/out.hlsl --report %t/report.json 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: FileCheck %s --input-file %t/out.hlsl
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t/report.json
// NOTE: note: HLSL vertex shader re-emitted by SPIRV-Cross instead of spliced into its own text: the splice declares the eye parameters only as a cbuffer (--eye-source=uniform-block); the output struct is SPIRV_Cross_Output (SV_Position last) and the file's other entry points are not in the output
// CHECK: struct SPIRV_Cross_Output
// REPORT: "notes": [
// REPORT-NEXT: "HLSL vertex shader re-emitted by SPIRV-Cross instead of spliced into its own text: the splice declares the eye parameters only as a cbuffer
// REPORT-NOT: "route": "hlsl-source-splice"
cbuffer Frame : register(b0) { float4x4 ViewProj; };

float4 VSMain(float3 p : POSITION) : SV_Position
{
    return mul(ViewProj, float4(p, 1.0));
}
