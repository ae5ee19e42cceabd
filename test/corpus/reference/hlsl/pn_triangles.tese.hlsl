// stereoshift-expect: shift
// D3D11 PN-triangles domain shader: cubic Bezier triangle from positions and normals, then perspective projection.

cbuffer DomainConstants : register(b2)
{
    float4x4 ViewProj;
};

struct PatchConstants
{
    float Edges[3] : SV_TessFactor;
    float Inside   : SV_InsideTessFactor;
};

struct DSInput
{
    float3 WorldPos : POSITION;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

struct DSOutput
{
    float4 Position : SV_Position;
    float3 Normal   : NORMAL;
    float2 UV       : TEXCOORD0;
};

float3 EdgeControl(float3 pi, float3 pj, float3 ni)
{
    return (2.0 * pi + pj - dot(pj - pi, ni) * ni) / 3.0;
}

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b4)
{
    float eyeSign;
    float separation;
    float convergence;
};

DSOutput stereoshift_shift_DSOutput(DSOutput stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Position.w))
    {
        precise float stereoshift_x = stereoshift_v.Position.x + (eyeSign * separation) * (stereoshift_v.Position.w - convergence);
        stereoshift_v.Position.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

/* stereoshift: moved to the wrapper: [domain("tri")] */
DSOutput DSMain_stereoshift_mono(PatchConstants pc, float3 bary : SV_DomainLocation, const OutputPatch<DSInput, 3> patch)
{
    float3 p0 = patch[0].WorldPos, p1 = patch[1].WorldPos, p2 = patch[2].WorldPos;
    float3 n0 = patch[0].Normal, n1 = patch[1].Normal, n2 = patch[2].Normal;
    float3 b210 = EdgeControl(p0, p1, n0), b120 = EdgeControl(p1, p0, n1);
    float3 b021 = EdgeControl(p1, p2, n1), b012 = EdgeControl(p2, p1, n2);
    float3 b102 = EdgeControl(p2, p0, n2), b201 = EdgeControl(p0, p2, n0);
    float3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    float3 b111 = e + (e - (p0 + p1 + p2) / 3.0) * 0.5;

    float u = bary.x, v = bary.y, w = bary.z;
    float3 pos = p0 * w * w * w + p1 * u * u * u + p2 * v * v * v
               + b210 * 3.0 * w * w * u + b120 * 3.0 * w * u * u + b201 * 3.0 * w * w * v
               + b021 * 3.0 * u * u * v + b102 * 3.0 * w * v * v + b012 * 3.0 * u * v * v
               + b111 * 6.0 * w * u * v;

    DSOutput output;
    output.Position = mul(ViewProj, float4(pos, 1.0));
    output.Normal = normalize(n0 * w + n1 * u + n2 * v);
    output.UV = patch[0].UV * w + patch[1].UV * u + patch[2].UV * v;
    return output;
}

// ---- stereoshift: entry point wrapper, shifts the clip position of 'DSMain_stereoshift_mono' ----
[domain("tri")]
DSOutput DSMain(PatchConstants pc, float3 bary : SV_DomainLocation, const OutputPatch<DSInput, 3> patch)
{
    return stereoshift_shift_DSOutput(DSMain_stereoshift_mono(pc, bary, patch));
}
// ---- end stereoshift ----
