matrix WorldViewProj;

SamplerState samLinear
{
    Filter = MIN_MAG_MIP_LINEAR;
};

struct PS_INPUT
{
    float4 Pos : SV_POSITION;
    float4 Color : COLOR0;
};

PS_INPUT RenderSceneVS(float4 Pos : POSITION, float4 Color : COLOR)
{
    PS_INPUT o;
    o.Pos = mul(Pos, WorldViewProj);
    o.Color = Color;
    return o;
}

float4 RenderScenePS(PS_INPUT i) : SV_Target
{
    return i.Color;
}

technique11 RenderScene
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, RenderSceneVS()));
        SetPixelShader(CompileShader(ps_5_0, RenderScenePS()));
    }
}
