// deferred-unprojection, view-ray form in HLSL: a point light over a G-buffer, the view ray
// interpolated from the vertex stage (TEXCOORD1) times the linear depth loaded at the pixel. P00
// comes from the projection the shader reads at [0][0] (a light radius in pixels).
// RUN: %stereoshift --validate-each --verify %s -e PSMain --report %t.json -o - | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
cbuffer LightConstants : register(b0)
{
    float4x4 Projection;
    float4 LightPositionView;   // xyz view-space position, w radius
    float4 LightColor;
};
Texture2D<float> LinearDepth : register(t0);
struct PSInput
{
    float4 Position : SV_Position;
    float3 ViewRay : TEXCOORD1;
};
float4 PSMain(PSInput input) : SV_Target
{
    float depth = LinearDepth.Load(int3(input.Position.xy, 0));
    float3 viewPos = input.ViewRay * depth;
    float3 toLight = LightPositionView.xyz - viewPos;
    float falloff = saturate(1.0 - length(toLight) / LightPositionView.w);
    float radiusPixels = LightPositionView.w * Projection[0][0];
    return float4(LightColor.rgb * falloff, radiusPixels);
}
// CHECK: float3 [[P:_[0-9]+]] = _input.ViewRay * depth;
// CHECK: [[X:_[0-9]+]].x = [[P]].x - (((eyeSign * separation) * {{.*}} - convergence)) * (1.0f / Projection[0].x));

// REPORT: "construct": "view ray * depth",
// REPORT-NEXT: "depth": "LinearDepth",
// REPORT: "form": "view ray interpolated from the vertex stage (input.ViewRay)",
// REPORT-NEXT: "projection_scale": "Projection[0][0]"
