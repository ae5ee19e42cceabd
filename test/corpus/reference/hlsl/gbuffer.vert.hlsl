struct VSInput
{
    float3 Position;
    float3 Normal;
    float4 Tangent;
    float2 UV;
};

struct VSOutput
{
    float4 Position;
    float3 Normal;
    float3 Tangent;
    float3 Bitangent;
    float2 UV;
    float ViewDepth;
};

cbuffer ObjectConstants : register(b0)
{
    column_major float4x4 World : packoffset(c0);
    column_major float4x4 ViewProj : packoffset(c4);
    column_major float4x4 View : packoffset(c8);
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
static float4 input_Tangent;
static float2 input_UV;
static float3 _entryPointOutput_Normal;
static float3 _entryPointOutput_Tangent;
static float3 _entryPointOutput_Bitangent;
static float2 _entryPointOutput_UV;
static float _entryPointOutput_ViewDepth;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    float4 input_Tangent : TANGENT;
    float2 input_UV : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_Normal : TEXCOORD0;
    float3 _entryPointOutput_Tangent : TEXCOORD1;
    float3 _entryPointOutput_Bitangent : TEXCOORD2;
    float2 _entryPointOutput_UV : TEXCOORD3;
    float _entryPointOutput_ViewDepth : TEXCOORD4;
    precise float4 gl_Position : SV_Position;
};

VSOutput _VSMain(VSInput _input)
{
    float4 world = mul(World, float4(_input.Position, 1.0f));
    VSOutput _output;
    _output.Position = mul(ViewProj, world);
    _output.Normal = normalize(mul(float3x3(World[0].xyz, World[1].xyz, World[2].xyz), _input.Normal));
    _output.Tangent = normalize(mul(float3x3(World[0].xyz, World[1].xyz, World[2].xyz), _input.Tangent.xyz));
    _output.Bitangent = cross(_output.Normal, _output.Tangent) * _input.Tangent.w;
    _output.UV = _input.UV;
    _output.ViewDepth = mul(View, world).z;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.Normal = input_Normal;
    _input.Tangent = input_Tangent;
    _input.UV = input_UV;
    VSInput param = _input;
    VSOutput flattenTemp = _VSMain(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_Normal = flattenTemp.Normal;
    _entryPointOutput_Tangent = flattenTemp.Tangent;
    _entryPointOutput_Bitangent = flattenTemp.Bitangent;
    _entryPointOutput_UV = flattenTemp.UV;
    _entryPointOutput_ViewDepth = flattenTemp.ViewDepth;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _175 = gl_Position.w - convergence;
        precise float _176 = eyeSign * separation;
        precise float _177 = _176 * _175;
        precise float _178 = gl_Position.x + _177;
        gl_Position.x = _178;
    }
}

SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_Tangent = stage_input.input_Tangent;
    input_UV = stage_input.input_UV;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Normal = _entryPointOutput_Normal;
    stage_output._entryPointOutput_Tangent = _entryPointOutput_Tangent;
    stage_output._entryPointOutput_Bitangent = _entryPointOutput_Bitangent;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    stage_output._entryPointOutput_ViewDepth = _entryPointOutput_ViewDepth;
    return stage_output;
}
