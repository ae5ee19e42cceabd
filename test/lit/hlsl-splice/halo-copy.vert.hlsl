// An output member that is a copy of the clip position (a halo copy, found by the halo pass) gets
// the same shift in the spliced helper, so it moves with the geometry.
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s
// CHECK: VSOut stereoshift_shift_VSOut(VSOut stereoshift_v)
// CHECK: stereoshift_v.pos.x = stereoshift_x;
// CHECK: if (eyeSign != 0.0f && abs(stereoshift_v.clipCopy.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.clipCopy.w))
// CHECK: stereoshift_v.clipCopy.x = stereoshift_x1;
// CHECK: return stereoshift_shift_VSOut(o);
cbuffer Frame : register(b0) { float4x4 ViewProj; };

struct VSOut
{
    float4 pos : SV_Position;
    float4 clipCopy : TEXCOORD1;
};

VSOut VSMain(float3 p : POSITION)
{
    VSOut o;
    o.pos = mul(ViewProj, float4(p, 1.0));
    o.clipCopy = o.pos;
    return o;
}
