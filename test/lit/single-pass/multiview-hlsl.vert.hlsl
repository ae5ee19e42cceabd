// --eye-source multiview, HLSL (a D3D11 tutorial-style vertex shader): eyeSign from SV_ViewID,
// shader model 6.1 (where SV_ViewID exists); re-emitted by SPIRV-Cross (the text splice carries
// the two-pass shift only). An explicit older shader model is refused.
// RUN: %stereoshift --eye-source multiview -e VS %s -o %t.hlsl 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: FileCheck %s --input-file %t.hlsl
// RUN: %not %stereoshift --eye-source multiview -e VS --target-version 50 %s -o %t.50.hlsl 2>&1 | FileCheck %s --check-prefix=SM50
// RUN: test ! -e %t.50.hlsl
cbuffer ConstantBuffer : register(b0)
{
    matrix World;
    matrix View;
    matrix Projection;
}
struct VS_OUTPUT
{
    float4 Pos : SV_POSITION;
    float4 Color : COLOR0;
};
VS_OUTPUT VS(float4 Pos : POSITION, float4 Color : COLOR)
{
    VS_OUTPUT output = (VS_OUTPUT)0;
    output.Pos = mul(Pos, World);
    output.Pos = mul(output.Pos, View);
    output.Pos = mul(output.Pos, Projection);
    output.Color = Color;
    return output;
}
// NOTE: note: HLSL vertex shader re-emitted by SPIRV-Cross
// CHECK: uint gl_ViewIndex : SV_ViewID;
// CHECK: ((gl_ViewIndex != 0) ? 1.0f : (-1.0f)) * separation
// SM50: error: --eye-source multiview: SV_ViewID needs shader model 6.1 (this is --target-version 50); drop --target-version or give 61 or later
