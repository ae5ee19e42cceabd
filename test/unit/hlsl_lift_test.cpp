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

}  // namespace
}  // namespace stereoshift
