// liftHlslIdioms (transpiler/frontend/hlsl_lift.h): the decompiler's idioms glslang refuses, in
// the forms it accepts, line for line; text without them is returned as it is.
#include "transpiler/frontend/hlsl_lift.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace stereoshift {
namespace {

size_t lines(const std::string& s) { return static_cast<size_t>(std::count(s.begin(), s.end(), '\n')); }

TEST(HlslLift, TheDecompilersCmpMacroBecomesAFunctionLikeNegation) {
  std::string text = "#define cmp -\nvoid main() { float r = cmp(0 < 1); r = 2 * cmp(r < 1); }\n";
  std::string what;
  std::string lifted = liftHlslIdioms(text, &what);
  EXPECT_EQ(lifted, "#define cmp(x) (0 - (x))\nvoid main() { float r = cmp(0 < 1); r = 2 * cmp(r < 1); }\n");
  EXPECT_EQ(what, "the decompiler's `#define cmp -` read as `#define cmp(x) (0 - (x))`");
  // Other macros named cmp, or spelled otherwise, are not the idiom.
  for (std::string other : {"#define cmp(a) (a)\n", "#define cmp - 1\n", "#define cmp-\n", "#define compare -\n"})
    EXPECT_EQ(liftHlslIdioms(other), other) << other;
}

TEST(HlslLift, IndexZeroOfSystemValuesIsDroppedKeepingColumns) {
  std::string text = "void main(float4 v0 : POSITION0, uint v1 : SV_VertexID0,\n out float4 o0 : SV_POSITION0,\n"
                     " out float4 o1 : TEXCOORD0, out float c : SV_ClipDistance0) {}\n";
  std::string what;
  std::string lifted = liftHlslIdioms(text, &what);
  EXPECT_EQ(lifted, "void main(float4 v0 : POSITION0, uint v1 : SV_VertexID ,\n out float4 o0 : SV_POSITION ,\n"
                    " out float4 o1 : TEXCOORD0, out float c : SV_ClipDistance0) {}\n");
  EXPECT_EQ(lifted.size(), text.size());
  EXPECT_EQ(lines(lifted), lines(text));
  EXPECT_EQ(what, "system-value semantics with index 0 (SV_VertexID0) read without it");
  // A ternary's `:` before a name ending in 0 is no semantic of that list.
  std::string ternary = "float f(bool b, float SV_X0) { return b ? 1 : SV_X0; }\n";
  EXPECT_EQ(liftHlslIdioms(ternary), ternary);
  std::string plain = "float4 main() : SV_Position { return 0; }\n";
  EXPECT_EQ(liftHlslIdioms(plain, &what), plain);
  EXPECT_TRUE(what.empty());
}

TEST(HlslLift, MatrixSwizzlesOfSeveralComponentsAreReadOneComponentAtATime) {
  std::string text =
      "cbuffer cb : register(b0) { row_major float4x4 World : packoffset(c0); half3x3 Tbn; float4x4 Bones[8]; }\n"
      "void main() {\n"
      "  r1.x = dot(r0.xyzw, World._m00_m10_m20_m30);\n"
      "  r1.yz = mul(r0.xyz, transpose(Tbn))._m01_m11; r2.xy = Tbn._11_22;\n"
      "  r3.x = dot(r0.xy, Bones[r4.x]._m00_m01) + World._m33;\n"
      "  r5 = asuint(Frame.Camera._m00_m10_m20_m30);\n"
      "}\n";
  std::string what;
  std::string lifted = liftHlslIdioms(text, &what);
  EXPECT_EQ(lifted,
            "cbuffer cb : register(b0) { row_major float4x4 World : packoffset(c0); half3x3 Tbn; float4x4 Bones[8]; }\n"
            "void main() {\n"
            "  r1.x = dot(r0.xyzw, float4(World._m00, World._m10, World._m20, World._m30));\n"
            // A call's result is not repeated (its swizzle is left as it is); the matrix's own scalar type.
            "  r1.yz = mul(r0.xyz, transpose(Tbn))._m01_m11; r2.xy = half2(Tbn._11, Tbn._22);\n"
            "  r3.x = dot(r0.xy, float2(Bones[r4.x]._m00, Bones[r4.x]._m01)) + World._m33;\n"
            // A member of a struct nobody declared as a matrix here: float.
            "  r5 = asuint(float4(Frame.Camera._m00, Frame.Camera._m10, Frame.Camera._m20, Frame.Camera._m30));\n"
            "}\n");
  EXPECT_EQ(lines(lifted), lines(text));
  EXPECT_EQ(what, "swizzles of several matrix components (World._m00_m10_m20_m30) read one component at a time");
  // Written swizzles, mixed or malformed spellings and single components stay as they are.
  for (std::string other : {"void f() { m._m00_m11 = r0.xy; m._11_22 += 1; }\n", "float x = m._m00_22 + m._m0;\n",
                            "float x = m._m00 + m._44 + m._m44_m00 + m._m00_m01_m02_m03_m10;\n",
                            "float2 v = f(i++)[0]._m00_m10 + a[i++]._m00_m10;\n"})
    EXPECT_EQ(liftHlslIdioms(other), other) << other;
}

TEST(HlslLift, UnnamedParametersAreNamedForTheParse) {
  std::string text =
      "struct S { float4 p : SV_Position; };\n"
      "S main(float3 p : POSITION, float3 : NORMAL, in uint : SV_VertexID,\n"
      "       vector<float, 4> /* unused */ : COLOR1, out float4 o : TEXCOORD0) : SV_Target\n"
      "{ float x = b ? p.x : p.y; S s; return s; }\n";
  std::string what;
  std::string lifted = liftHlslIdioms(text, &what);
  EXPECT_EQ(lifted,
            "struct S { float4 p : SV_Position; };\n"
            "S main(float3 p : POSITION, float3 stereoshift_unnamed0 : NORMAL, in uint stereoshift_unnamed1 : SV_VertexID,\n"
            "       vector<float, 4> stereoshift_unnamed2 /* unused */ : COLOR1, out float4 o : TEXCOORD0) : SV_Target\n"
            "{ float x = b ? p.x : p.y; S s; return s; }\n");
  EXPECT_EQ(what, "3 parameter(s) declared without a name given one");
  // Named parameters, struct members, register bindings, ternaries and case labels stay as they are.
  for (std::string other : {"float4 main(float4 pos : POSITION, uint id : SV_VertexID) : SV_Position { return pos; }\n",
                            "Texture2D t : register(t0);\nstruct V { float4 c : COLOR; };\n",
                            "float f(float a, bool b) { switch (a) { case 1: return b ? a : 0; } return 0; }\n",
                            "static const float k = g(a ? b : c, d);\n"})
    EXPECT_EQ(liftHlslIdioms(other), other) << other;
}

}  // namespace
}  // namespace stereoshift
