// stereoshift-expect: fragment
// Book-style pixel shader named `*_ps.hlsl`: the terrain colour from a tiled texture, entry point PSMain.
Texture2D Diffuse : register(t0);
SamplerState LinearWrap : register(s0);

struct VertexOut
{
    float4 PosH : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

float4 PSMain(VertexOut pin) : SV_Target
{
    return Diffuse.Sample(LinearWrap, pin.Tex * 16.0f);
}
