// A register the splice cannot take (--hlsl-register naming one the file already uses) is refused
// with a clear file:line:col error and no output, on every route: re-emitting by SPIRV-Cross would
// not resolve it either.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %stereoshift --hlsl-register 0 %s -o %t/out.hlsl 2>&1 | FileCheck %s
// RUN: test ! -e %t/out.hlsl
// CHECK: refusal.vert.hlsl:[[@LINE+4]]:26: error: cannot splice the stereo shift: register(b0) is already used; choose another cbuffer register
// CHECK-NEXT: cbuffer Frame : register(b0) { float4x4 ViewProj; };
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: 1 error generated.
cbuffer Frame : register(b0) { float4x4 ViewProj; };

float4 VSMain(float3 p : POSITION) : SV_Position
{
    return mul(ViewProj, float4(p, 1.0));
}
