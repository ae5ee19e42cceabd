struct PSInput
{
    float4 Position;
};

cbuffer LightConstants : register(b1)
{
    column_major float4x4 InvViewProj : packoffset(c0);
    float3 LightPosition : packoffset(c4);
    float LightRadius : packoffset(c4.w);
    float3 LightColor : packoffset(c5);
    float Padding : packoffset(c5.w);
    float2 InvViewportSize : packoffset(c6);
    float2 Padding2 : packoffset(c6.z);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};

Texture2D<float4> DepthBuffer : register(t0);
Texture2D<float4> NormalRough : register(t2);
Texture2D<float4> AlbedoMetal : register(t1);

static float4 gl_FragCoord;
static float4 _entryPointOutput;

struct SPIRV_Cross_Input
{
    float4 gl_FragCoord : SV_Position;
};

struct SPIRV_Cross_Output
{
    float4 _entryPointOutput : SV_Target0;
};

float4 _PSMain(PSInput _input)
{
    int3 pixel = int3(int2(_input.Position.xy), 0);
    float depth = DepthBuffer.Load(int3(pixel.xy, pixel.z)).x;
    float2 uv = _input.Position.xy * InvViewportSize;
    float2 ndc = float2((uv.x * 2.0f) - 1.0f, 1.0f - (uv.y * 2.0f));
    float4 _82 = mul(InvViewProj, float4(ndc, depth, 1.0f));
    float4 _203 = _82 - (float4(InvViewProj[0].x, InvViewProj[1].x, InvViewProj[2].x, InvViewProj[3].x) * ((eyeSign * separation) * (1.0f - (convergence * _82.w))));
    bool4 _205 = (eyeSign != 0.0f).xxxx;
    float4 q = float4(_205.x ? _203.x : _82.x, _205.y ? _203.y : _82.y, _205.z ? _203.z : _82.z, _205.w ? _203.w : _82.w);
    float3 worldPos = q.xyz / q.w.xxx;
    float3 toLight = LightPosition - worldPos;
    float dist = length(toLight);
    if (dist > LightRadius)
    {
        discard;
    }
    float3 n = (NormalRough.Load(int3(pixel.xy, pixel.z)).xyz * 2.0f) - 1.0f.xxx;
    float3 albedo = AlbedoMetal.Load(int3(pixel.xy, pixel.z)).xyz;
    float falloff = clamp(1.0f - ((dist * dist) / (LightRadius * LightRadius)), 0.0f, 1.0f);
    float ndl = clamp(dot(normalize(n), toLight / dist.xxx), 0.0f, 1.0f);
    return float4((((albedo * LightColor) * ndl) * falloff) * falloff, 0.0f);
}

void frag_main()
{
    PSInput _input;
    _input.Position = gl_FragCoord;
    PSInput param = _input;
    float4 _181 = _PSMain(param);
    _entryPointOutput = _181;
}

SPIRV_Cross_Output PSMain(SPIRV_Cross_Input stage_input)
{
    gl_FragCoord = stage_input.gl_FragCoord;
    gl_FragCoord.w = 1.0 / gl_FragCoord.w;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output._entryPointOutput = _entryPointOutput;
    return stage_output;
}
