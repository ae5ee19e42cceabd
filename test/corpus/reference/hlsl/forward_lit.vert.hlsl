struct VSInput
{
    float3 Position;
    float3 Normal;
    float2 UV;
};

struct VSOutput
{
    float4 Position;
    float3 WorldNormal;
    float2 UV;
    float4 Tint;
};

cbuffer PerObject : register(b0)
{
    row_major float4x4 WorldViewProj : packoffset(c0);
    row_major float4x4 WorldMatrix : packoffset(c4);
    float4 MaterialTint : packoffset(c8);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float3 input_Position;
static float3 input_Normal;
static float2 input_UV;
static float3 _entryPointOutput_WorldNormal;
static float2 _entryPointOutput_UV;
static float4 _entryPointOutput_Tint;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    float2 input_UV : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_WorldNormal : TEXCOORD0;
    float2 _entryPointOutput_UV : TEXCOORD1;
    float4 _entryPointOutput_Tint : COLOR0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _VSMain(VSInput _input)
{
    VSOutput _output;
    _output.Position = mul(float4(_input.Position, 1.0f), WorldViewProj);
    _output.WorldNormal = normalize(mul(_input.Normal, float3x3(WorldMatrix[0].xyz, WorldMatrix[1].xyz, WorldMatrix[2].xyz)));
    _output.UV = _input.UV;
    _output.Tint = MaterialTint;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.Normal = input_Normal;
    _input.UV = input_UV;
    VSInput param = _input;
    VSOutput flattenTemp = _VSMain(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_WorldNormal = flattenTemp.WorldNormal;
    _entryPointOutput_UV = flattenTemp.UV;
    _entryPointOutput_Tint = flattenTemp.Tint;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _127 = gl_Position.w - convergence;
        precise float _128 = eyeSign * separation;
        precise float _129 = _128 * _127;
        precise float _130 = gl_Position.x + _129;
        gl_Position.x = _130;
    }
}

SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_UV = stage_input.input_UV;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_WorldNormal = _entryPointOutput_WorldNormal;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    stage_output._entryPointOutput_Tint = _entryPointOutput_Tint;
    return stage_output;
}
