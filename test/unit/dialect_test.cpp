// The front end's dialects (transpiler/frontend/dialect.h): one object per input language, in a
// list; each one's copy for the analysis (what it lifts), and the language decision that picks it.
#include "transpiler/frontend/dialect.h"

#include <gtest/gtest.h>

namespace stereoshift {
namespace {

TEST(FrontEndDialects, OnePerLanguageInAList) {
  ASSERT_EQ(frontEndDialects().size(), 2u);
  EXPECT_STREQ(dialectOf(SourceLanguage::Hlsl).name(), "hlsl");
  EXPECT_STREQ(dialectOf(SourceLanguage::Glsl).name(), "glsl");
  for (const auto& dialect : frontEndDialects()) EXPECT_EQ(&dialectOf(dialect->language()), dialect.get());
}

// A decompiled dump's swizzle of several matrix components (glslang types it as an integer): the
// analysis copy reads each component alone; an effect file's technique is blanked.
TEST(FrontEndDialects, HlslLiftsDecompilerIdiomsAndBlanksEffects) {
  const FrontEndDialect& hlsl = dialectOf(SourceLanguage::Hlsl);
  const std::string dump =
      "cbuffer cb0 : register(b0) { float4x4 World : packoffset(c0); }\n"
      "void main(float4 v0 : POSITION0, out float4 o0 : SV_Position0)\n"
      "{\n"
      "  o0.x = dot(v0.xyzw, World._m00_m10_m20_m30);\n"
      "  o0.yzw = v0.yzw;\n"
      "}\n";
  std::string what;
  std::string copy = hlsl.liftForAnalysis(dump, &what);
  EXPECT_FALSE(what.empty());
  EXPECT_EQ(copy.find("_m00_m10_m20_m30"), std::string::npos) << copy;
  EXPECT_NE(copy.find("World._m00"), std::string::npos) << copy;
  EXPECT_EQ(std::count(copy.begin(), copy.end(), '\n'), std::count(dump.begin(), dump.end(), '\n'));  // lines kept

  const std::string effect = "float4 VS(float4 p : POSITION) : SV_Position { return p; }\n"
                             "technique T { pass P { VertexShader = compile vs_4_0 VS(); } }\n";
  std::string blanked = hlsl.liftForAnalysis(effect, nullptr);
  EXPECT_EQ(blanked.find("technique"), std::string::npos) << blanked;
  EXPECT_NE(blanked.find("float4 VS("), std::string::npos);
}

// GLSL lifts only what glslang reads more narrowly than drivers: a line continuation is joined (its
// line count kept); a text with nothing of that is its own copy.
TEST(FrontEndDialects, GlslLiftsOnlyWhatGlslangReadsNarrowly) {
  const FrontEndDialect& glsl = dialectOf(SourceLanguage::Glsl);
  const std::string continued = "#version 330\n#define SCALE(x) \\\n  ((x) * 2.0)\n"
                                "in vec4 p;\nvoid main() { gl_Position = SCALE(p); }\n";
  std::string what;
  std::string copy = glsl.liftForAnalysis(continued, &what);
  EXPECT_FALSE(what.empty());
  EXPECT_EQ(copy.find("\\\n"), std::string::npos) << copy;
  EXPECT_EQ(std::count(copy.begin(), copy.end(), '\n'), std::count(continued.begin(), continued.end(), '\n'));
  const std::string plain = "#version 330\nin vec4 p;\nvoid main() { gl_Position = p; }\n";
  EXPECT_EQ(glsl.liftForAnalysis(plain, &what), plain);
  EXPECT_TRUE(what.empty());
}

// The decision that picks a dialect: -x, then the extension, then the text (HLSL kept in a file
// named by its stage only; `#version` makes it GLSL).
TEST(FrontEndDialects, TheLanguageDecisionPicksTheDialect) {
  const std::string hlslText = "cbuffer C : register(b0) { float4x4 M; };\n"
                               "float4 main(float4 p : POSITION) : SV_Position { return mul(p, M); }\n";
  EXPECT_STREQ(dialectOf(decideLanguage("shaders/blur.vert", hlslText, std::nullopt).language).name(), "hlsl");
  EXPECT_STREQ(dialectOf(decideLanguage("a.vert", "#version 450\nvoid main() {}\n", std::nullopt).language).name(),
               "glsl");
  EXPECT_STREQ(dialectOf(decideLanguage("a.glsl", hlslText, std::nullopt).language).name(), "glsl");
  EXPECT_STREQ(dialectOf(decideLanguage("a.vert", "void main() {}\n", SourceLanguage::Hlsl).language).name(), "hlsl");
}

}  // namespace
}  // namespace stereoshift
