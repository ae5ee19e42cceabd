// stereoshift-expect: shift
// D3D11 mesh-explosion geometry shader: pushes each triangle along its face normal and emits a front copy and a scorched back copy via a helper.

cbuffer ExplodeConstants : register(b1)
{
    float4x4 ViewProj;
    float    ExplodeAmount;
    float    Gravity;
    float2   Padding;
};

struct GSInput
{
    float4 WorldPos : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct GSOutput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
    float4 Color    : COLOR0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b3)
{
    float eyeSign;
    float separation;
    float convergence;
};

GSOutput stereoshift_shift_GSOutput(GSOutput stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Position.w))
    {
        precise float stereoshift_x = stereoshift_v.Position.x + (eyeSign * separation) * (stereoshift_v.Position.w - convergence);
        stereoshift_v.Position.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

void EmitShardVertex(inout TriangleStream<GSOutput> stream, float3 world, float3 normal, float2 uv, float4 color)
{
    GSOutput v;
    v.Position = mul(ViewProj, float4(world, 1.0));
    v.Normal = normal;
    v.UV = uv;
    v.Color = color;
    stream.Append(stereoshift_shift_GSOutput(v));
}

[maxvertexcount(6)]
void GSMain(triangle GSInput input[3], inout TriangleStream<GSOutput> stream)
{
    float3 p0 = input[0].WorldPos.xyz, p1 = input[1].WorldPos.xyz, p2 = input[2].WorldPos.xyz;
    float3 faceNormal = normalize(cross(p1 - p0, p2 - p0));
    float3 offset = faceNormal * ExplodeAmount - float3(0.0, Gravity * ExplodeAmount * ExplodeAmount, 0.0);

    [unroll] for (int i = 0; i < 3; ++i)
        EmitShardVertex(stream, input[i].WorldPos.xyz + offset, input[i].Normal, input[i].UV, float4(1, 1, 1, 1));
    stream.RestartStrip();

    // Back face of the shard, slightly behind, reversed winding, darkened.
    [unroll] for (int j = 2; j >= 0; --j)
        EmitShardVertex(stream, input[j].WorldPos.xyz + offset - faceNormal * 0.01, -input[j].Normal, input[j].UV, float4(0.2, 0.15, 0.1, 1));
    stream.RestartStrip();
}
