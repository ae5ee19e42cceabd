// stereoshift-expect: shift
// packoffset-laid-out constants, explicit registers and a halo copy of the clip position in the output struct.
cbuffer Transforms : register(b2)
{
    float4x4 WorldViewProj : packoffset(c0);
    float4 Tint : packoffset(c4);
    float Scale : packoffset(c5.x);
};

Texture2D Detail : register(t3);
SamplerState Aniso : register(s1);

struct VSOut
{
    float4 Clip : SV_Position;
    float4 ClipCopy : TEXCOORD1;
    float2 UV : TEXCOORD0;
};

VSOut main(float3 pos : POSITION, float2 uv : TEXCOORD0)
{
    VSOut o;
    o.Clip = mul(WorldViewProj, float4(pos * Scale, 1.0));
    o.ClipCopy = o.Clip;
    o.UV = uv;
    return o;
}

float4 mainPS(VSOut i) : SV_Target
{
    return Detail.Sample(Aniso, i.UV) * Tint;
}
