// stereoshift-expect: shift
// Stage-named HLSL domain shader: barycentric interpolation of the triangle patch, height-map displacement, perspective projection.

struct UBO
{
    float4x4 viewProj;
    float displacement;
    float padding0;
    float2 padding1;
};

[[vk::binding(0, 0)]]
cbuffer ubo : register(b0) { UBO ubo; }

[[vk::binding(1, 0)]] Texture2D heightMap : register(t1);
[[vk::binding(1, 0)]] SamplerState heightSampler : register(s1);

struct HSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
};

struct ConstantsHSOutput
{
    float TessLevelOuter[3] : SV_TessFactor;
    float TessLevelInner : SV_InsideTessFactor;
};

struct DSOutput
{
    float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
[[vk::location(1)]] float Height : TEXCOORD1;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b2)
{
    float eyeSign;
    float separation;
    float convergence;
};

DSOutput stereoshift_shift_DSOutput(DSOutput stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Pos.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Pos.w))
    {
        precise float stereoshift_x = stereoshift_v.Pos.x + (eyeSign * separation) * (stereoshift_v.Pos.w - convergence);
        stereoshift_v.Pos.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

/* stereoshift: moved to the wrapper: [domain("tri")] */
DSOutput main_stereoshift_mono(ConstantsHSOutput input, float3 TessCoord : SV_DomainLocation, const OutputPatch<HSOutput, 3> patch)
{
    DSOutput output = (DSOutput)0;
    float3 pos = TessCoord.x * patch[0].Pos.xyz + TessCoord.y * patch[1].Pos.xyz + TessCoord.z * patch[2].Pos.xyz;
    float2 uv = TessCoord.x * patch[0].UV + TessCoord.y * patch[1].UV + TessCoord.z * patch[2].UV;
    float height = heightMap.SampleLevel(heightSampler, uv, 0.0).r;
    pos.y += height * ubo.displacement;
    output.Pos = mul(ubo.viewProj, float4(pos, 1.0));
    output.UV = uv;
    output.Height = height;
    return output;
}

// ---- stereoshift: entry point wrapper, shifts the clip position of 'main_stereoshift_mono' ----
[domain("tri")]
DSOutput main(ConstantsHSOutput input, float3 TessCoord : SV_DomainLocation, const OutputPatch<HSOutput, 3> patch)
{
    return stereoshift_shift_DSOutput(main_stereoshift_mono(input, TessCoord, patch));
}
// ---- end stereoshift ----
