struct VertexIn
{
    float3 PosL;
    float3 NormalL;
    float2 Tex;
    float3 TangentL;
};

struct VertexOut
{
    float4 PosH;
    float2 Tex;
    float3 EyePosT;
    float3 PosT;
};

cbuffer cbPerFrame : register(b0)
{
    column_major float4x4 gWorld : packoffset(c0);
    column_major float4x4 gViewProj : packoffset(c4);
    float3 gEyePosW : packoffset(c8);
    float gHeightScale : packoffset(c8.w);
};

cbuffer StereoParams : register(b2)
{
    float eyeSign : packoffset(c0);
    float separation : packoffset(c0.y);
    float convergence : packoffset(c0.z);
};


static float4 gl_Position;
static float3 vin_PosL;
static float3 vin_NormalL;
static float2 vin_Tex;
static float3 vin_TangentL;
static float2 _entryPointOutput_Tex;
static float3 _entryPointOutput_EyePosT;
static float3 _entryPointOutput_PosT;

struct SPIRV_Cross_Input
{
    float3 vin_PosL : POSITION;
    float3 vin_NormalL : NORMAL;
    float2 vin_Tex : TEXCOORD;
    float3 vin_TangentL : TANGENT;
};

struct SPIRV_Cross_Output
{
    float2 _entryPointOutput_Tex : TEXCOORD0;
    float3 _entryPointOutput_EyePosT : TEXCOORD1;
    float3 _entryPointOutput_PosT : TEXCOORD2;
    precise float4 gl_Position : SV_Position;
};

// Returns the determinant of a 2x2 matrix.
float spvDet2x2(float a1, float a2, float b1, float b2)
{
    return a1 * b2 - b1 * a2;
}

// Returns the determinant of a 3x3 matrix.
float spvDet3x3(float a1, float a2, float a3, float b1, float b2, float b3, float c1, float c2, float c3)
{
    return a1 * spvDet2x2(b2, b3, c2, c3) - b1 * spvDet2x2(a2, a3, c2, c3) + c1 * spvDet2x2(a2, a3, b2, b3);
}

// Returns the inverse of a matrix, by using the algorithm of calculating the classical
// adjoint and dividing by the determinant. The contents of the matrix are changed.
float4x4 spvInverse(float4x4 m)
{
    float4x4 adj;	// The adjoint matrix (inverse after dividing by determinant)

    // Create the transpose of the cofactors, as the classical adjoint of the matrix.
    adj[0][0] =  spvDet3x3(m[1][1], m[1][2], m[1][3], m[2][1], m[2][2], m[2][3], m[3][1], m[3][2], m[3][3]);
    adj[0][1] = -spvDet3x3(m[0][1], m[0][2], m[0][3], m[2][1], m[2][2], m[2][3], m[3][1], m[3][2], m[3][3]);
    adj[0][2] =  spvDet3x3(m[0][1], m[0][2], m[0][3], m[1][1], m[1][2], m[1][3], m[3][1], m[3][2], m[3][3]);
    adj[0][3] = -spvDet3x3(m[0][1], m[0][2], m[0][3], m[1][1], m[1][2], m[1][3], m[2][1], m[2][2], m[2][3]);

    adj[1][0] = -spvDet3x3(m[1][0], m[1][2], m[1][3], m[2][0], m[2][2], m[2][3], m[3][0], m[3][2], m[3][3]);
    adj[1][1] =  spvDet3x3(m[0][0], m[0][2], m[0][3], m[2][0], m[2][2], m[2][3], m[3][0], m[3][2], m[3][3]);
    adj[1][2] = -spvDet3x3(m[0][0], m[0][2], m[0][3], m[1][0], m[1][2], m[1][3], m[3][0], m[3][2], m[3][3]);
    adj[1][3] =  spvDet3x3(m[0][0], m[0][2], m[0][3], m[1][0], m[1][2], m[1][3], m[2][0], m[2][2], m[2][3]);

    adj[2][0] =  spvDet3x3(m[1][0], m[1][1], m[1][3], m[2][0], m[2][1], m[2][3], m[3][0], m[3][1], m[3][3]);
    adj[2][1] = -spvDet3x3(m[0][0], m[0][1], m[0][3], m[2][0], m[2][1], m[2][3], m[3][0], m[3][1], m[3][3]);
    adj[2][2] =  spvDet3x3(m[0][0], m[0][1], m[0][3], m[1][0], m[1][1], m[1][3], m[3][0], m[3][1], m[3][3]);
    adj[2][3] = -spvDet3x3(m[0][0], m[0][1], m[0][3], m[1][0], m[1][1], m[1][3], m[2][0], m[2][1], m[2][3]);

    adj[3][0] = -spvDet3x3(m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2], m[3][0], m[3][1], m[3][2]);
    adj[3][1] =  spvDet3x3(m[0][0], m[0][1], m[0][2], m[2][0], m[2][1], m[2][2], m[3][0], m[3][1], m[3][2]);
    adj[3][2] = -spvDet3x3(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[3][0], m[3][1], m[3][2]);
    adj[3][3] =  spvDet3x3(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]);

    // Calculate the determinant as a combination of the cofactors of the first row.
    float det = (adj[0][0] * m[0][0]) + (adj[0][1] * m[1][0]) + (adj[0][2] * m[2][0]) + (adj[0][3] * m[3][0]);

    // Divide the classical adjoint matrix by the determinant.
    // If determinant is zero, matrix is not invertable, so leave it unchanged.
    return (det != 0.0f) ? (adj * (1.0f / det)) : m;
}

VertexOut _main(VertexIn vin)
{
    float4 posW = mul(gWorld, float4(vin.PosL, 1.0f));
    float3 N = normalize(mul(float3x3(gWorld[0].xyz, gWorld[1].xyz, gWorld[2].xyz), vin.NormalL));
    float3 T = normalize(mul(float3x3(gWorld[0].xyz, gWorld[1].xyz, gWorld[2].xyz), vin.TangentL));
    float3 B = cross(N, T);
    float3x3 toTangent = float3x3(float3(T), float3(B), float3(N));
    VertexOut vout;
    vout.EyePosT = mul(toTangent, gEyePosW + mul(spvInverse(gViewProj), float4((eyeSign * separation) * convergence, 0.0f, 0.0f, 0.0f)).xyz);
    vout.PosT = mul(toTangent, posW.xyz);
    vout.Tex = vin.Tex;
    vout.PosH = mul(gViewProj, posW);
    return vout;
}

void vert_main()
{
    VertexIn vin;
    vin.PosL = vin_PosL;
    vin.NormalL = vin_NormalL;
    vin.Tex = vin_Tex;
    vin.TangentL = vin_TangentL;
    VertexIn param = vin;
    VertexOut flattenTemp = _main(param);
    gl_Position = flattenTemp.PosH;
    _entryPointOutput_Tex = flattenTemp.Tex;
    _entryPointOutput_EyePosT = flattenTemp.EyePosT;
    _entryPointOutput_PosT = flattenTemp.PosT;
    if ((eyeSign != 0.0f) && ((abs(gl_Position.w - 1.0f) > 9.9999997473787516355514526367188e-06f) && (!isinf(gl_Position.w))))
    {
        precise float _178 = gl_Position.w - convergence;
        precise float _179 = eyeSign * separation;
        precise float _180 = _179 * _178;
        precise float _181 = gl_Position.x + _180;
        gl_Position.x = _181;
    }
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    vin_PosL = stage_input.vin_PosL;
    vin_NormalL = stage_input.vin_NormalL;
    vin_Tex = stage_input.vin_Tex;
    vin_TangentL = stage_input.vin_TangentL;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output._entryPointOutput_Tex = _entryPointOutput_Tex;
    stage_output._entryPointOutput_EyePosT = _entryPointOutput_EyePosT;
    stage_output._entryPointOutput_PosT = _entryPointOutput_PosT;
    return stage_output;
}
