// -e picks the HLSL entry point among several; the output keeps that name as its entry point.
// Without -e the stage's conventional name (VSMain) is used when there is no main.
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
// SHADOW: mul(LightViewProj,
// SHADOW: eyeSign * separation
// SHADOW: SPIRV_Cross_Output VSShadow(SPIRV_Cross_Input stage_input)
// SHADOW-NOT: VSMain
// DEFAULT: mul(ViewProj,
// DEFAULT: SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
// MISSING: error: entry point 'NoSuchEntry' not found
// MISSING: {{^}}1 error generated.
