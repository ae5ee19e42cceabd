struct VSInput
{
    float3 Pos;
};

struct VSOutput
{
    float4 Pos;
    float3 UVW;
};

struct UBO
{
    column_major float4x4 projection;
    column_major float4x4 view;
};

static const VSOutput _21 = { 0.0f.xxxx, 0.0f.xxx };

cbuffer ubo : register(b0)
{
    UBO ubo : packoffset(c0);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float3 input_Pos;
static float3 _entryPointOutput_UVW;

struct SPIRV_Cross_Input
{
    float3 input_Pos : POSITION0;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_UVW : TEXCOORD0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    VSOutput _output = _21;
    _output.UVW = _input.Pos;
    float3 rotated = mul(float3x3(ubo.view[0].xyz, ubo.view[1].xyz, ubo.view[2].xyz), _input.Pos);
    float4 clip = mul(ubo.projection, float4(rotated, 1.0f));
    _output.Pos = clip.xyww;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Pos = input_Pos;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Pos;
    _entryPointOutput_UVW = flattenTemp.UVW;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _111 = gl_Position.w - convergence;
        precise float _112 = eyeSign * separation;
        precise float _113 = _112 * _111;
        precise float _114 = gl_Position.x + _113;
        gl_Position.x = _114;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Pos = stage_input.input_Pos;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_UVW = _entryPointOutput_UVW;
    return stage_output;
}
