struct VSInput
{
    float3 Position;
    float3 Normal;
    float2 UV;
    uint4 BoneIndices;
    float4 BoneWeights;
};

struct VSOutput
{
    float4 Position;
    float3 Normal;
    float2 UV;
};

cbuffer SkinningConstants : register(b0)
{
    column_major float4x4 BonePalette[96] : packoffset(c0);
};

cbuffer CameraConstants : register(b1)
{
    column_major float4x4 View : packoffset(c0);
    column_major float4x4 Projection : packoffset(c4);
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
static float2 input_UV;
static uint4 input_BoneIndices;
static float4 input_BoneWeights;
static float3 _entryPointOutput_Normal;
static float2 _entryPointOutput_UV;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    float2 input_UV : TEXCOORD0;
    uint4 input_BoneIndices : BLENDINDICES;
    float4 input_BoneWeights : BLENDWEIGHT;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_Normal : NORMAL;
    float2 _entryPointOutput_UV : TEXCOORD0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    float4x4 _41 = BonePalette[_input.BoneIndices.x] * _input.BoneWeights.x;
    float4x4 _49 = BonePalette[_input.BoneIndices.y] * _input.BoneWeights.y;
    float4x4 _62 = float4x4(_41[0] + _49[0], _41[1] + _49[1], _41[2] + _49[2], _41[3] + _49[3]);
    float4x4 _70 = BonePalette[_input.BoneIndices.z] * _input.BoneWeights.z;
    float4x4 _83 = float4x4(_62[0] + _70[0], _62[1] + _70[1], _62[2] + _70[2], _62[3] + _70[3]);
    float4x4 _91 = BonePalette[_input.BoneIndices.w] * _input.BoneWeights.w;
    float4x4 skin = float4x4(_83[0] + _91[0], _83[1] + _91[1], _83[2] + _91[2], _83[3] + _91[3]);
    float4 world = mul(skin, float4(_input.Position, 1.0f));
    VSOutput _output;
    _output.Normal = normalize(mul(float3x3(skin[0].xyz, skin[1].xyz, skin[2].xyz), _input.Normal));
    _output.UV = _input.UV;
    _output.Position = mul(Projection, mul(View, world));
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.Normal = input_Normal;
    _input.UV = input_UV;
    _input.BoneIndices = input_BoneIndices;
    _input.BoneWeights = input_BoneWeights;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_Normal = flattenTemp.Normal;
    _entryPointOutput_UV = flattenTemp.UV;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _218 = gl_Position.w - convergence;
        precise float _219 = eyeSign * separation;
        precise float _220 = _219 * _218;
        precise float _221 = gl_Position.x + _220;
        gl_Position.x = _221;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_UV = stage_input.input_UV;
    input_BoneIndices = stage_input.input_BoneIndices;
    input_BoneWeights = stage_input.input_BoneWeights;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Normal = _entryPointOutput_Normal;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    return stage_output;
}
