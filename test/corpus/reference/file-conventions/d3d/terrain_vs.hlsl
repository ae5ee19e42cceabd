struct VertexOut
{
    float4 PosH;
    float2 Tex;
};

cbuffer TerrainConstants : register(b0)
{
    column_major float4x4 WorldViewProj : packoffset(c0);
    float HeightScale : packoffset(c4);
    float3 Padding : packoffset(c4.y);
};

cbuffer StereoParams : register(b1)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};

Texture2D<float4> HeightMap : register(t0);
SamplerState PointClamp : register(s0);

static float4 gl_Position;
static float3 posL;
static float2 tex;
static float2 _entryPointOutput_Tex;

struct SPIRV_Cross_Input
{
    float3 posL : POSITION;
    float2 tex : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float2 _entryPointOutput_Tex : TEXCOORD0;
    precise float4 gl_Position : SV_Position;
};

VertexOut _VSMain(float3 posL_1, float2 tex_1)
{
    float height = HeightMap.SampleLevel(PointClamp, tex_1, 0.0f).x * HeightScale;
    VertexOut vout;
    vout.PosH = mul(float4(posL_1.x, height, posL_1.z, 1.0f), WorldViewProj);
    vout.Tex = tex_1;
    return vout;
}

void vert_main()
{
    float3 posL_1 = posL;
    float2 tex_1 = tex;
    float3 param = posL_1;
    float2 param_1 = tex_1;
    VertexOut flattenTemp = _VSMain(param, param_1);
    gl_Position = flattenTemp.PosH;
    _entryPointOutput_Tex = flattenTemp.Tex;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _117 = gl_Position.w - convergence;
        precise float _118 = eyeSign * separation;
        precise float _119 = _118 * _117;
        precise float _120 = gl_Position.x + _119;
        gl_Position.x = _120;
    }
}

SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
{
    posL = stage_input.posL;
    tex = stage_input.tex;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Tex = _entryPointOutput_Tex;
    return stage_output;
}
