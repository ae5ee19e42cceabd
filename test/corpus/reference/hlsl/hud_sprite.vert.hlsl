struct VSInput
{
    float2 Position;
    float2 UV;
    float4 Color;
};

struct VSOutput
{
    float4 Position;
    float2 UV;
    float4 Color;
};

cbuffer HudConstants : register(b0)
{
    column_major float4x4 OrthoProjection : packoffset(c0);
    float2 ScreenOffset : packoffset(c4);
    float UiScale : packoffset(c4.z);
    float Padding : packoffset(c4.w);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float2 input_Position;
static float2 input_UV;
static float4 input_Color;
static float2 _entryPointOutput_UV;
static float4 _entryPointOutput_Color;

struct SPIRV_Cross_Input
{
    float2 input_Position : POSITION;
    float2 input_UV : TEXCOORD0;
    float4 input_Color : COLOR0;
};

struct SPIRV_Cross_Output
{
    float2 _entryPointOutput_UV : TEXCOORD0;
    float4 _entryPointOutput_Color : COLOR0;
    precise float4 gl_Position : SV_Position;
};

VSOutput _main(VSInput _input)
{
    float2 pixel = (_input.Position * UiScale) + ScreenOffset;
    VSOutput _output;
    _output.Position = mul(OrthoProjection, float4(pixel, 0.0f, 1.0f));
    _output.UV = _input.UV;
    _output.Color = _input.Color;
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    _input.UV = input_UV;
    _input.Color = input_Color;
    VSInput param = _input;
    VSOutput flattenTemp = _main(param);
    gl_Position = flattenTemp.Position;
    _entryPointOutput_UV = flattenTemp.UV;
    _entryPointOutput_Color = flattenTemp.Color;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _112 = gl_Position.w - convergence;
        precise float _113 = eyeSign * separation;
        precise float _114 = _113 * _112;
        precise float _115 = gl_Position.x + _114;
        gl_Position.x = _115;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    input_UV = stage_input.input_UV;
    input_Color = stage_input.input_Color;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_UV = _entryPointOutput_UV;
    stage_output._entryPointOutput_Color = _entryPointOutput_Color;
    return stage_output;
}
