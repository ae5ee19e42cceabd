// per-eye-view in HLSL where a helper's parameter has the camera's name: a wrap by name could move
// the wrong value, so the splice declines with the reason and SPIRV-Cross re-emits the IR's fix.
// RUN: %stereoshift --validate-each %s -o %t.hlsl 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.hlsl | FileCheck %s
// NOTE: note: HLSL vertex shader re-emitted by SPIRV-Cross instead of spliced into its own text: cannot splice the stereo shift: a parameter named 'gEyePosW' hides the camera
// CHECK-NOT: stereoshift_eye_
// CHECK: InvViewProj
cbuffer Frame : register(b0)
{
    float4x4 World;
    float4x4 ViewProj;
    float4x4 InvViewProj;
    float3 gEyePosW;
};

struct VSOut
{
    float4 pos : SV_Position;
    float3 viewTS : TEXCOORD0;
};

float3 toEye(float3 gEyePosW, float3 p) { return gEyePosW - p; }

VSOut main(float3 position : POSITION, float3 normal : NORMAL, float4 tangent : TANGENT)
{
    VSOut o;
    float4 world = mul(World, float4(position, 1.0f));
    float3 n = normalize(mul((float3x3)World, normal));
    float3 t = normalize(mul((float3x3)World, tangent.xyz));
    float3x3 toTangent = float3x3(t, cross(n, t) * tangent.w, n);
    o.viewTS = mul(toTangent, toEye(gEyePosW, world.xyz));
    o.pos = mul(ViewProj, world);
    return o;
}
