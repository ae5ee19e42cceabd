struct VSInput
{
    float3 Position;
    float3 Normal;
    float2 UV;
    float4 Color;
    uint InstanceId;
};

struct VSOutput
{
    float4 Position;
    float3 Normal;
    float2 UV;
    float3 Tint;
};

struct InstanceData
{
    column_major float4x4 World;
    float4 TintAndPhase;
};

ByteAddressBuffer Instances : register(t0);
cbuffer SceneConstants : register(b0)
{
    column_major float4x4 ViewProj : packoffset(c0);
    float3 WindDirection : packoffset(c4);
    float Time : packoffset(c4.w);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static int gl_InstanceIndex;
static float3 input_Position;
static float3 input_Normal;
static float2 input_UV;
static float4 input_Color;
static float3 _entryPointOutput_Normal;
static float2 _entryPointOutput_UV;
static float3 _entryPointOutput_Tint;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    float2 input_UV : TEXCOORD0;
    float4 input_Color : COLOR0;
    uint gl_InstanceIndex : SV_InstanceID;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_Normal : NORMAL;
    float2 _entryPointOutput_UV : TEXCOORD0;
    float3 _entryPointOutput_Tint : COLOR0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _VSMain(VSInput _input)
{
    InstanceData _35;
    _35.World = asfloat(uint4x4(Instances.Load(_input.InstanceId * 80 + 0), Instances.Load(_input.InstanceId * 80 + 16), Instances.Load(_input.InstanceId * 80 + 32), Instances.Load(_input.InstanceId * 80 + 48), Instances.Load(_input.InstanceId * 80 + 4), Instances.Load(_input.InstanceId * 80 + 20), Instances.Load(_input.InstanceId * 80 + 36), Instances.Load(_input.InstanceId * 80 + 52), Instances.Load(_input.InstanceId * 80 + 8), Instances.Load(_input.InstanceId * 80 + 24), Instances.Load(_input.InstanceId * 80 + 40), Instances.Load(_input.InstanceId * 80 + 56), Instances.Load(_input.InstanceId * 80 + 12), Instances.Load(_input.InstanceId * 80 + 28), Instances.Load(_input.InstanceId * 80 + 44), Instances.Load(_input.InstanceId * 80 + 60)));
    _35.TintAndPhase = asfloat(Instances.Load4(_input.InstanceId * 80 + 64));
    InstanceData inst;
    inst.World = _35.World;
    inst.TintAndPhase = _35.TintAndPhase;
    float4 world = mul(inst.World, float4(_input.Position, 1.0f));
    float sway = sin((Time * 1.7000000476837158203125f) + inst.TintAndPhase.w) * _input.Color.x;
    float4 _83 = world;
    float3 _85 = _83.xyz + ((WindDirection * sway) * 0.1500000059604644775390625f);
    world.x = _85.x;
    world.y = _85.y;
    world.z = _85.z;
    VSOutput _output;
    _output.Position = mul(ViewProj, world);
    _output.Normal = normalize(mul(float3x3(inst.World[0].xyz, inst.World[1].xyz, inst.World[2].xyz), _input.Normal));
    _output.UV = _input.UV;
    _output.Tint = inst.TintAndPhase.xyz;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.Normal = input_Normal;
    _input.UV = input_UV;
    _input.Color = input_Color;
    _input.InstanceId = uint(gl_InstanceIndex);
    VSInput param = _input;
    VSOutput flattenTemp = _VSMain(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_Normal = flattenTemp.Normal;
    _entryPointOutput_UV = flattenTemp.UV;
    _entryPointOutput_Tint = flattenTemp.Tint;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _194 = gl_Position.w - convergence;
        precise float _195 = eyeSign * separation;
        precise float _196 = _195 * _194;
        precise float _197 = gl_Position.x + _196;
        gl_Position.x = _197;
    }
}

SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
{
    gl_InstanceIndex = int(stage_input.gl_InstanceIndex);
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_UV = stage_input.input_UV;
    input_Color = stage_input.input_Color;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Normal = _entryPointOutput_Normal;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    stage_output._entryPointOutput_Tint = _entryPointOutput_Tint;
    return stage_output;
}
