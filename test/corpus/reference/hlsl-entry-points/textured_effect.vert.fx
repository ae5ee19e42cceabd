// stereoshift-expect: shift
// Effects 11 file: a textured mesh with its sampler and rasterizer state and a technique11 that compiles VS and PS.
matrix World;
matrix View;
matrix Projection;
Texture2D txDiffuse;

SamplerState samLinear
{
    Filter = MIN_MAG_MIP_LINEAR;
    AddressU = Wrap;
    AddressV = Wrap;
};

RasterizerState rsSolid
{
    FillMode = SOLID;
    CullMode = BACK;
};

struct VS_INPUT
{
    float4 Pos : POSITION;
    float2 Tex : TEXCOORD0;
};

struct PS_INPUT
{
    float4 Pos : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b1)
{
    float eyeSign;
    float separation;
    float convergence;
};

PS_INPUT stereoshift_shift_PS_INPUT(PS_INPUT stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Pos.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Pos.w))
    {
        precise float stereoshift_x = stereoshift_v.Pos.x + (eyeSign * separation) * (stereoshift_v.Pos.w - convergence);
        stereoshift_v.Pos.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

PS_INPUT VS( VS_INPUT input )
{
    PS_INPUT output = (PS_INPUT)0;
    output.Pos = mul( input.Pos, World );
    output.Pos = mul( output.Pos, View );
    output.Pos = mul( output.Pos, Projection );
    output.Tex = input.Tex;
    return stereoshift_shift_PS_INPUT(output);
}

float4 PS( PS_INPUT input ) : SV_Target
{
    return txDiffuse.Sample( samLinear, input.Tex );
}

technique11 Render
{
    pass P0
    {
        SetVertexShader( CompileShader( vs_5_0, VS() ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_5_0, PS() ) );
        SetRasterizerState( rsSolid );
    }
}
