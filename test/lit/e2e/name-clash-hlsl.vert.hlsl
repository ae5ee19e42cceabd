// HLSL cbuffer members share one global scope: a `separation` member of the application's cbuffer
// makes the injected one `separation_stereo` (warning), and the shift uses it.
// RUN: %stereoshift --verify %s -o %t.out.hlsl 2>&1 | FileCheck %s --check-prefix=WARN
// RUN: %rmchecks %t.out.hlsl | FileCheck %s
// RUN: glslangValidator -D -V -S vert -e main -o %t.spv %t.out.hlsl
// WARN: warning: the shader already declares 'separation'; the injected one is named 'separation_stereo'
cbuffer Frame : register(b0)
{
  float4x4 WorldViewProj;
  float separation;
};
// CHECK: cbuffer Frame : register(b0)
// CHECK: float separation;
// CHECK: cbuffer StereoParams : register(b1)
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation_stereo;
// CHECK-NEXT: float convergence;
float4 main(float3 pos : POSITION) : SV_Position
{
  return mul(WorldViewProj, float4(pos * separation, 1.0));
}
// CHECK: precise float stereoshift_x = stereoshift_v.x + (eyeSign * separation_stereo)
// CHECK: float4(pos * separation, 1.0)
