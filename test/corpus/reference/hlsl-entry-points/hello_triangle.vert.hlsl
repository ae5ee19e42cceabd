// stereoshift-expect: shift
// D3D12 sample style: PSInput shared by VSMain and PSMain, a scene constant buffer with one matrix.
cbuffer SceneConstantBuffer : register(b0)
{
    float4x4 worldViewProj;
    float4 tint;
};

struct PSInput
{
    float4 position : SV_POSITION;
    float4 color : COLOR;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b1)
{
    float eyeSign;
    float separation;
    float convergence;
};

PSInput stereoshift_shift_PSInput(PSInput stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.position.w))
    {
        precise float stereoshift_x = stereoshift_v.position.x + (eyeSign * separation) * (stereoshift_v.position.w - convergence);
        stereoshift_v.position.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

PSInput VSMain(float4 position : POSITION, float4 color : COLOR)
{
    PSInput result;

    result.position = mul(position, worldViewProj);
    result.color = color * tint;

    return stereoshift_shift_PSInput(result);
}

float4 PSMain(PSInput input) : SV_TARGET
{
    return input.color;
}
