// stereoshift-expect: 2d
// Full-screen triangle from SV_VertexID with its post-process PS in one file: clip w is 1, no shift.
Texture2D SceneColor : register(t0);
SamplerState PointClamp : register(s0);

struct FullscreenOut
{
    float4 Position : SV_Position;
    float2 UV : TEXCOORD0;
};

FullscreenOut VSMain(uint id : SV_VertexID)
{
    FullscreenOut o;
    o.UV = float2((id << 1) & 2, id & 2);
    o.Position = float4(o.UV * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
    return o;
}

float4 PSMain(FullscreenOut i) : SV_Target
{
    float3 c = SceneColor.Sample(PointClamp, i.UV).rgb;
    return float4(c / (1.0 + c), 1.0);
}
