struct VSInput
{
    float3 Position;
};

struct VSOutput
{
    float4 Position;
};

cbuffer LightVolumeConstants : register(b0)
{
    column_major float4x4 ViewProj : packoffset(c0);
    float3 LightPosition : packoffset(c4);
    float LightRadius : packoffset(c4.w);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float3 input_Position;

struct SPIRV_Cross_Input
{
    float3 input_Position : POSITION;
};

struct SPIRV_Cross_Output
{
    precise float4 gl_Position : SV_Position;
};

VSOutput _VSMain(VSInput _input)
{
    float3 world = LightPosition + ((_input.Position * LightRadius) * 1.08000004291534423828125f);
    VSOutput _output;
    _output.Position = mul(ViewProj, float4(world, 1.0f));
    return _output;
}

void vert_main()
{
    VSInput _input;
    _input.Position = input_Position;
    VSInput param = _input;
    VSOutput _64 = _VSMain(param);
    float4 _65 = _64.Position;
    gl_Position = _65;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _93 = gl_Position.w - convergence;
        precise float _94 = eyeSign * separation;
        precise float _95 = _94 * _93;
        precise float _96 = gl_Position.x + _95;
        gl_Position.x = _96;
    }
}

SPIRV_Cross_Output VSMain(SPIRV_Cross_Input stage_input)
{
    input_Position = stage_input.input_Position;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    return stage_output;
}
