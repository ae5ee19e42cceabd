// deferred-unprojection in HLSL: mul(InvViewProj, float4(ndc, depth, 1)) is `v * M` in SPIR-V (the
// cbuffer matrix's SPIR-V columns are HLSL rows), so the matrix's column 0 is element 0 of each
// SPIR-V column. The SV_Position input reaches the user function through glslang's wrapper (a
// struct copied into a parameter) and the depth is a Texture2D.Load.
// RUN: %stereoshift --validate-each --verify %s --report %t.json -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift --validate-each %s --target spirv-asm -o - | FileCheck %s --check-prefix=SPIRV
cbuffer Frame : register(b0)
{
    float4x4 InvViewProj;
    float2 InvViewportSize;
};
Texture2D<float> DepthBuffer : register(t0);
struct PSInput { float4 Position : SV_Position; };
float4 PSMain(PSInput input) : SV_Target
{
    float depth = DepthBuffer.Load(int3(input.Position.xy, 0));
    float2 uv = input.Position.xy * InvViewportSize;
    float2 ndc = float2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
    float4 q = mul(InvViewProj, float4(ndc, depth, 1.0));
    return float4(q.xyz / q.w, 1.0);
}
// The HLSL text keeps its own: the product wrapped in the per-eye helper, which reads InvM's column
// of NDC x element by element (M[i][0]), beside the eye parameters' cbuffer.
// CHECK: cbuffer StereoParams : register(b1)
// CHECK: float4 stereoshift_unproject_InvViewProj(float4 stereoshift_q)
// CHECK-NEXT: {
// CHECK-NEXT: return eyeSign != 0.0f ? stereoshift_q - float4(InvViewProj[0][0], InvViewProj[1][0], InvViewProj[2][0], InvViewProj[3][0]) * ((eyeSign * separation) * (1.0f - convergence * stereoshift_q.w)) : stereoshift_q;
// CHECK: float4 q = stereoshift_unproject_InvViewProj(mul(InvViewProj, float4(ndc, depth, 1.0)));

// SPIRV: [[M:%[0-9]+]] = OpLoad %mat4v4float
// SPIRV-NEXT: [[Q:%[0-9]+]] = OpVectorTimesMatrix %v4float {{%[0-9]+}} [[M]]
// SPIRV-NEXT: [[M00:%[0-9]+]] = OpCompositeExtract %float [[M]] 0 0
// SPIRV-NEXT: [[M10:%[0-9]+]] = OpCompositeExtract %float [[M]] 1 0
// SPIRV-NEXT: [[M20:%[0-9]+]] = OpCompositeExtract %float [[M]] 2 0
// SPIRV-NEXT: [[M30:%[0-9]+]] = OpCompositeExtract %float [[M]] 3 0
// SPIRV-NEXT: [[COL0:%[0-9]+]] = OpCompositeConstruct %v4float [[M00]] [[M10]] [[M20]] [[M30]]
// SPIRV: OpVectorTimesScalar %v4float [[COL0]]

// REPORT: "depth": "DepthBuffer",
// REPORT: "matrix": "InvViewProj",
// REPORT-NEXT: "ndc": "SV_Position"
// REPORT: "result": "changed"
