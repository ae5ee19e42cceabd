// stereoshift-expect: fragment
// D3D11 HUD sprite pixel shader: atlas sprite times vertex colour, with a greyed-out disabled state.

cbuffer HudPixelConstants : register(b1)
{
    float Disabled;
    float Opacity;
    float2 Padding;
};

Texture2D    SpriteAtlas   : register(t0);
SamplerState SpriteSampler : register(s0);

struct PSInput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
    float4 Color    : COLOR0;
};

float4 main(PSInput input) : SV_Target
{
    float4 color = SpriteAtlas.Sample(SpriteSampler, input.UV) * input.Color;
    float grey = dot(color.rgb, float3(0.3, 0.59, 0.11));
    color.rgb = lerp(color.rgb, grey.xxx * 0.6, Disabled);
    color.a *= Opacity;
    return color;
}
