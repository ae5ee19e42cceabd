// --eye-source instanced, HLSL with SV_InstanceID (a DirectX instancing sample reading per-instance
// matrices from a structured buffer): the eye goes to SV_RenderTargetArrayIndex from the vertex
// shader (D3D12 VPAndRTArrayIndexFromAnyShaderFeedingRasterizer), or to SV_ViewportArrayIndex with
// --eye-route viewport; the instance the shader reads is the original one.
// RUN: %stereoshift --eye-source instanced -e VSMain %s -o %t.hlsl
// RUN: FileCheck %s --input-file %t.hlsl
// RUN: %stereoshift --eye-source instanced --eye-route viewport -e VSMain %s -o - | FileCheck %s --check-prefix=VIEWPORT
cbuffer PerFrame : register(b0) { float4x4 ViewProj; };
StructuredBuffer<float4x4> InstanceWorld : register(t0);
struct VSOut { float4 Pos : SV_POSITION; float Id : TEXCOORD0; };
VSOut VSMain(float3 pos : POSITION, uint iid : SV_InstanceID)
{
    VSOut o;
    o.Pos = mul(mul(float4(pos, 1), InstanceWorld[iid]), ViewProj);
    o.Id = iid;
    return o;
}
// CHECK: nointerpolation int stereoEye : TEXCOORD15;
// CHECK: int stereoLayer : SV_RENDERTARGETARRAYINDEX;
// CHECK: stereoLayer = [[EYE:_[0-9]+]];
// CHECK: uint iid = uint(gl_InstanceIndex) >> uint(1);
// VIEWPORT: uint gl_ViewportIndex : SV_ViewportArrayIndex;
