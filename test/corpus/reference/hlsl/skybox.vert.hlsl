struct VSInput
{
    float3 Position;
};

struct VSOutput
{
    float4 Position;
    float3 Direction;
    float4 Tint;
};

cbuffer SkyConstants : register(b0)
{
    column_major float4x4 ViewRotationProj : packoffset(c0);
    float4 SkyTint : packoffset(c4);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float3 input_Position;
static float3 _entryPointOutput_Direction;
static float4 _entryPointOutput_Tint;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_Direction : TEXCOORD0;
    float4 _entryPointOutput_Tint : COLOR0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _VSMain(VSInput _input)
{
    float4 pos = mul(ViewRotationProj, float4(_input.Position, 1.0f));
    VSOutput _output;
    _output.Position = pos.xyww;
    _output.Direction = _input.Position;
    _output.Tint = SkyTint;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    VSInput param = _input;
    VSOutput flattenTemp = _VSMain(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_Direction = flattenTemp.Direction;
    _entryPointOutput_Tint = flattenTemp.Tint;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _101 = gl_Position.w - convergence;
        precise float _102 = eyeSign * separation;
        precise float _103 = _102 * _101;
        precise float _104 = gl_Position.x + _103;
        gl_Position.x = _104;
    }
}

SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Direction = _entryPointOutput_Direction;
    stage_output._entryPointOutput_Tint = _entryPointOutput_Tint;
    return stage_output;
}
