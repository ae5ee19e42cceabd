// -e picks the HLSL entry point among several and restricts the shift to it; the output keeps the
// whole file, the other entry point as written. Without -e every vertex entry point is shifted.
// RUN: %stereoshift --verify -e VSShadow %s -o - | %rmchecks | FileCheck %s --check-prefix=SHADOW
// RUN: %stereoshift --verify --entry-point=VSShadow %s -o - | %rmchecks | FileCheck %s --check-prefix=SHADOW
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
// RUN: %not %stereoshift -e NoSuchEntry %s -o %t.out 2>&1 | FileCheck %s --check-prefix=MISSING
cbuffer Frame : register(b0) { float4x4 ViewProj; float4x4 LightViewProj; };

float4 VSMain(float3 pos : POSITION) : SV_Position
{
  return mul(ViewProj, float4(pos, 1.0));
}

float4 VSShadow(float3 pos : POSITION) : SV_Position
{
  return mul(LightViewProj, float4(pos, 1.0));
}
// SHADOW: float4 VSMain(float3 pos : POSITION) : SV_Position
// SHADOW-NEXT: {
// SHADOW-NEXT: return mul(ViewProj, float4(pos, 1.0));
// SHADOW: eyeSign * separation
// SHADOW: float4 VSShadow(float3 pos : POSITION) : SV_Position
// SHADOW-NEXT: {
// SHADOW-NEXT: return stereoshift_shift_position(mul(LightViewProj, float4(pos, 1.0)));
// DEFAULT: return stereoshift_shift_position(mul(ViewProj, float4(pos, 1.0)));
// DEFAULT: return stereoshift_shift_position(mul(LightViewProj, float4(pos, 1.0)));
// MISSING: error: entry point 'NoSuchEntry' not found
// MISSING: {{^}}1 error generated.
