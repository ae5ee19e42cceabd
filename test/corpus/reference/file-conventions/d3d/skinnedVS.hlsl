struct VSInput
{
    float3 Position;
    float3 Normal;
    uint4 BoneIndices;
    float4 BoneWeights;
};

struct VSOutput
{
    float4 Position;
    float3 Normal;
};

cbuffer Bones : register(b1)
{
    column_major float4x4 BoneMatrices[64] : packoffset(c0);
};

cbuffer PerFrame : register(b0)
{
    column_major float4x4 ViewProjection : packoffset(c0);
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
static uint4 input_BoneIndices;
static float4 input_BoneWeights;
static float3 _entryPointOutput_Normal;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
    float3 input_Normal : NORMAL;
    uint4 input_BoneIndices : BLENDINDICES;
    float4 input_BoneWeights : BLENDWEIGHT;
};

struct SPIRV_Cross_Output
{
    float3 _entryPointOutput_Normal : NORMAL;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    float4x4 _40 = BoneMatrices[_input.BoneIndices.x] * _input.BoneWeights.x;
    float4x4 _48 = BoneMatrices[_input.BoneIndices.y] * _input.BoneWeights.y;
    float4x4 _61 = float4x4(_40[0] + _48[0], _40[1] + _48[1], _40[2] + _48[2], _40[3] + _48[3]);
    float4x4 _69 = BoneMatrices[_input.BoneIndices.z] * _input.BoneWeights.z;
    float4x4 _82 = float4x4(_61[0] + _69[0], _61[1] + _69[1], _61[2] + _69[2], _61[3] + _69[3]);
    float4x4 _90 = BoneMatrices[_input.BoneIndices.w] * _input.BoneWeights.w;
    float4x4 skin = float4x4(_82[0] + _90[0], _82[1] + _90[1], _82[2] + _90[2], _82[3] + _90[3]);
    float4 world = mul(float4(_input.Position, 1.0f), skin);
    VSOutput _output;
    _output.Position = mul(world, ViewProjection);
    _output.Normal = mul(_input.Normal, float3x3(skin[0].xyz, skin[1].xyz, skin[2].xyz));
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.Normal = input_Normal;
    _input.BoneIndices = input_BoneIndices;
    _input.BoneWeights = input_BoneWeights;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_Normal = flattenTemp.Normal;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _200 = gl_Position.w - convergence;
        precise float _201 = eyeSign * separation;
        precise float _202 = _201 * _200;
        precise float _203 = gl_Position.x + _202;
        gl_Position.x = _203;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_Normal = stage_input.input_Normal;
    input_BoneIndices = stage_input.input_BoneIndices;
    input_BoneWeights = stage_input.input_BoneWeights;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Normal = _entryPointOutput_Normal;
    return stage_output;
}
