// stereoshift-expect: shift
// A VS whose output struct has SV_Position between other members: the order is what the PS links by.
cbuffer Camera : register(b0)
{
    float4x4 ViewProj;
    float3 CameraPos;
};

struct VertexOut
{
    float3 WorldPos : POSITION0;
    float3 Normal : NORMAL0;
    float4 Pos : SV_Position;
    float2 UV : TEXCOORD0;
    float Fog : FOG;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b1)
{
    float eyeSign;
    float separation;
    float convergence;
};

VertexOut stereoshift_shift_VertexOut(VertexOut stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Pos.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Pos.w))
    {
        precise float stereoshift_x = stereoshift_v.Pos.x + (eyeSign * separation) * (stereoshift_v.Pos.w - convergence);
        stereoshift_v.Pos.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VertexOut VSMain(float3 pos : POSITION, float3 nrm : NORMAL, float2 uv : TEXCOORD)
{
    VertexOut o;
    o.WorldPos = pos;
    o.Normal = nrm;
    o.Pos = mul(ViewProj, float4(pos, 1.0f));
    o.UV = uv;
    o.Fog = saturate(length(pos - CameraPos) / 100.0f);
    return stereoshift_shift_VertexOut(o);
}

float4 PSMain(VertexOut i) : SV_Target
{
    float3 color = saturate(dot(normalize(i.Normal), float3(0.0f, 1.0f, 0.0f))).xxx;
    return float4(lerp(color, float3(0.5f, 0.6f, 0.7f), i.Fog), 1.0f);
}
