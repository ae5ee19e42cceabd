struct VSInput
{
    float3 Position;
    float3 Normal;
    float2 UV;
};

struct VSOutput
{
    float4 Position;
    float2 UV;
};

cbuffer ShadowConstants : register(b0)
{
    column_major float4x4 LightWorldViewProj : packoffset(c0);
    float NormalOffset : packoffset(c4);
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
static float2 _entryPointOutput_UV;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    float2 input_UV : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float2 _entryPointOutput_UV : TEXCOORD0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    float3 biased = _input.Position + (_input.Normal * NormalOffset);
    VSOutput _output;
    _output.Position = mul(LightWorldViewProj, float4(biased, 1.0f));
    _output.UV = _input.UV;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.Normal = input_Normal;
    _input.UV = input_UV;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_UV = flattenTemp.UV;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _108 = gl_Position.w - convergence;
        precise float _109 = eyeSign * separation;
        precise float _110 = _109 * _108;
        precise float _111 = gl_Position.x + _110;
        gl_Position.x = _111;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_UV = stage_input.input_UV;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    return stage_output;
}
