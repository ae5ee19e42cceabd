struct VSInput
{
    float3 Pos;
    float3 Normal;
    float2 UV;
};

struct VSOutput
{
    float4 Pos;
    float2 UV;
    float3 Normal;
    float3 LightVec;
};

struct UBO
{
    column_major float4x4 projection;
    column_major float4x4 view;
    column_major float4x4 model;
    float4 lightPos;
};

static const VSOutput _23 = { 0.0f.xxxx, 0.0f.xx, 0.0f.xxx, 0.0f.xxx };

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
static float3 input_Normal;
static float2 input_UV;
static float2 _entryPointOutput_UV;
static float3 _entryPointOutput_Normal;
static float3 _entryPointOutput_LightVec;

struct SPIRV_Cross_Input
{
    float3 input_Pos : POSITION0;
    float3 input_Normal : NORMAL0;
    float2 input_UV : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float2 _entryPointOutput_UV : TEXCOORD0;
    float3 _entryPointOutput_Normal : NORMAL0;
    float3 _entryPointOutput_LightVec : TEXCOORD1;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    VSOutput _output = _23;
    float4 worldPos = mul(ubo.model, float4(_input.Pos, 1.0f));
    _output.UV = _input.UV;
    _output.Normal = mul(float3x3(ubo.model[0].xyz, ubo.model[1].xyz, ubo.model[2].xyz), _input.Normal);
    _output.LightVec = ubo.lightPos.xyz - worldPos.xyz;
    _output.Pos = mul(ubo.projection, mul(ubo.view, worldPos));
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Pos = input_Pos;
    _input.Normal = input_Normal;
    _input.UV = input_UV;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Pos;
    _entryPointOutput_UV = flattenTemp.UV;
    _entryPointOutput_Normal = flattenTemp.Normal;
    _entryPointOutput_LightVec = flattenTemp.LightVec;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _143 = gl_Position.w - convergence;
        precise float _144 = eyeSign * separation;
        precise float _145 = _144 * _143;
        precise float _146 = gl_Position.x + _145;
        gl_Position.x = _146;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Pos = stage_input.input_Pos;
    input_Normal = stage_input.input_Normal;
    input_UV = stage_input.input_UV;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    stage_output._entryPointOutput_Normal = _entryPointOutput_Normal;
    stage_output._entryPointOutput_LightVec = _entryPointOutput_LightVec;
    return stage_output;
}
