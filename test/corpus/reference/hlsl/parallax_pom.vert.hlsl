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
    float2 UV;
    float3 ViewTS;
    float3 NormalWS;
};

cbuffer ObjectConstants : register(b1)
{
    column_major float4x4 World : packoffset(c0);
    column_major float4x4 WorldInvTranspose : packoffset(c4);
};

cbuffer FrameConstants : register(b0)
{
    column_major float4x4 ViewProj : packoffset(c0);
    column_major float4x4 InvViewProj : packoffset(c4);
    float3 CameraPosition : packoffset(c8);
    float Time : packoffset(c8.w);
    float4 ViewportSize : packoffset(c9);
};

cbuffer StereoParams : register(b3)
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
static float2 _entryPointOutput_UV;
static float3 _entryPointOutput_ViewTS;
static float3 _entryPointOutput_NormalWS;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    float4 input_Tangent : TANGENT;
    float2 input_UV : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float2 _entryPointOutput_UV : TEXCOORD0;
    float3 _entryPointOutput_ViewTS : TEXCOORD1;
    float3 _entryPointOutput_NormalWS : TEXCOORD2;
    precise float4 gl_Position : SV_Position;
};

float3x3 WorldToTangentBasis(float3 n, float3 t, float handedness)
{
    float3 b = cross(n, t) * handedness;
    return float3x3(float3(t), float3(b), float3(n));
}

VSOutput _main(VSInput _input)
{
    float4 world = mul(World, float4(_input.Position, 1.0f));
    float3 n = normalize(mul(float3x3(WorldInvTranspose[0].xyz, WorldInvTranspose[1].xyz, WorldInvTranspose[2].xyz), _input.Normal));
    float3 t = normalize(mul(float3x3(World[0].xyz, World[1].xyz, World[2].xyz), _input.Tangent.xyz));
    float3 param = n;
    float3 param_1 = t;
    float param_2 = _input.Tangent.w;
    float3x3 toTangent = WorldToTangentBasis(param, param_1, param_2);
    VSOutput _output;
    _output.Position = mul(ViewProj, world);
    _output.UV = _input.UV;
    _output.ViewTS = mul(toTangent, (CameraPosition + mul(InvViewProj, float4((eyeSign * separation) * convergence, 0.0f, 0.0f, 0.0f)).xyz) - world.xyz);
    _output.NormalWS = n;
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
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_UV = flattenTemp.UV;
    _entryPointOutput_ViewTS = flattenTemp.ViewTS;
    _entryPointOutput_NormalWS = flattenTemp.NormalWS;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _204 = gl_Position.w - convergence;
        precise float _205 = eyeSign * separation;
        precise float _206 = _205 * _204;
        precise float _207 = gl_Position.x + _206;
        gl_Position.x = _207;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_Tangent = stage_input.input_Tangent;
    input_UV = stage_input.input_UV;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    stage_output._entryPointOutput_ViewTS = _entryPointOutput_ViewTS;
    stage_output._entryPointOutput_NormalWS = _entryPointOutput_NormalWS;
    return stage_output;
}
