cbuffer Camera : register(b0) { float4x4 ViewProj; };
Texture2D HeightMap : register(t0);
SamplerState LinearClamp : register(s0);
struct VSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
VSOut main(float3 p : POSITION, float2 uv : TEXCOORD0)
{
    VSOut o;
    float h = HeightMap.SampleLevel(LinearClamp, uv, 0).r;
    o.pos = mul(ViewProj, float4(p.x, h, p.z, 1.0f));
    o.uv = uv;
    return o;
}
