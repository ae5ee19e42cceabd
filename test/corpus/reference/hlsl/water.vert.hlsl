struct VSInput
{
    float3 Position;
    float2 UV;
};

struct VSOutput
{
    float4 Position;
    float4 ClipPos;
    float2 ScreenUV;
    float2 UV0;
    float2 UV1;
};

cbuffer WaterConstants : register(b0)
{
    column_major float4x4 World : packoffset(c0);
    column_major float4x4 ViewProj : packoffset(c4);
    float2 ScrollSpeed : packoffset(c8);
    float Time : packoffset(c8.z);
    float Padding : packoffset(c8.w);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float3 input_Position;
static float2 input_UV;
static float4 _entryPointOutput_ClipPos;
static float2 _entryPointOutput_ScreenUV;
static float2 _entryPointOutput_UV0;
static float2 _entryPointOutput_UV1;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float2 input_UV : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 _entryPointOutput_ClipPos : TEXCOORD0;
    float2 _entryPointOutput_ScreenUV : TEXCOORD1;
    float2 _entryPointOutput_UV0 : TEXCOORD2;
    float2 _entryPointOutput_UV1 : TEXCOORD3;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    float4 world = mul(World, float4(_input.Position, 1.0f));
    VSOutput _output;
    _output.Position = mul(ViewProj, world);
    _output.ClipPos = _output.Position;
    _output.ScreenUV = ((_output.Position.xy / _output.Position.w.xx) * float2(0.5f, -0.5f)) + 0.5f.xx;
    _output.UV0 = _input.UV + (ScrollSpeed * Time);
    _output.UV1 = (_input.UV * 1.7000000476837158203125f) - ((ScrollSpeed.yx * Time) * 0.60000002384185791015625f);
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.UV = input_UV;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Position;
    float4 _116 = flattenTemp.ClipPos;
    precise float _138 = _116.w - convergence;
    precise float _139 = eyeSign * separation;
    precise float _140 = _139 * _138;
    precise float _141 = _116.x + _140;
    _116.x = ((eyeSign != 0.0f) && ((abs(_116.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(_116.w)))) ? _141 : _116.x;
    _entryPointOutput_ClipPos = _116;
    _entryPointOutput_ScreenUV = flattenTemp.ScreenUV;
    _entryPointOutput_UV0 = flattenTemp.UV0;
    _entryPointOutput_UV1 = flattenTemp.UV1;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _178 = gl_Position.w - convergence;
        precise float _179 = eyeSign * separation;
        precise float _180 = _179 * _178;
        precise float _181 = gl_Position.x + _180;
        gl_Position.x = _181;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_UV = stage_input.input_UV;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_ClipPos = _entryPointOutput_ClipPos;
    stage_output._entryPointOutput_ScreenUV = _entryPointOutput_ScreenUV;
    stage_output._entryPointOutput_UV0 = _entryPointOutput_UV0;
    stage_output._entryPointOutput_UV1 = _entryPointOutput_UV1;
    return stage_output;
}
