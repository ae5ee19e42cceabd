// parseGlslangLog (transpiler/frontend/glslang_log.*): glslang's info log into file:line:col
// diagnostics. The two line forms, the follow-up lines it drops, and the edge cases of the split:
// file names with colons and digits, tokens with quotes, lines that are not glslang's.
#include "transpiler/frontend/glslang_log.h"

#include <gtest/gtest.h>

namespace stereoshift {
namespace {

std::vector<Diagnostic> parse(const std::string& log, const std::string& source = "void main() {\n  foo = 1;\n}\n") {
  Diagnostics out;
  parseGlslangLog(log, "main.vert", {{"main.vert", source}}, out);
  return out.all();
}

TEST(GlslangLog, LocatedErrorGetsTheTokensColumn) {
  auto d = parse("ERROR: main.vert:2: 'foo' : undeclared identifier \n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].severity, Severity::Error);
  EXPECT_EQ(d[0].file, "main.vert");
  EXPECT_EQ(d[0].line, 2);
  EXPECT_EQ(d[0].column, 3);
  EXPECT_EQ(d[0].message, "'foo' : undeclared identifier");
}

// HLSL's parser, where it gives up (a stray `}`), writes `file(line): error at column N, message`
// without "ERROR:": its line and column are kept, and the text there is named.
TEST(GlslangLog, HlslParserLineKeepsItsLineAndColumn) {
  auto d = parse("main.vert(3): error at column 1, HLSL parsing failed.\n", "float4 main() : SV_Position {\n}\n}\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].severity, Severity::Error);
  EXPECT_EQ(d[0].file, "main.vert");
  EXPECT_EQ(d[0].line, 3);
  EXPECT_EQ(d[0].column, 1);
  EXPECT_EQ(d[0].message, "HLSL parsing failed at '}'");
  // A file name with parentheses: the last "(" before the marker opens the line number.
  d = parse("dir(1)/a.hlsl(12): error at column 7, HLSL parsing failed.\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].file, "dir(1)/a.hlsl");
  EXPECT_EQ(d[0].line, 12);
  EXPECT_EQ(d[0].column, 7);
  // Not that form: a line that only looks like it.
  EXPECT_TRUE(parse("a(x): error at column 1, HLSL parsing failed.\n").empty());
  EXPECT_TRUE(parse("a(1): error at column y, HLSL parsing failed.\n").empty());
}

TEST(GlslangLog, FileZeroAndEmptyTokenMeanTheMainFileAndTheLinesFirstCharacter) {
  auto d = parse("WARNING: 0:3: '' : something odd\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].severity, Severity::Warning);
  EXPECT_EQ(d[0].file, "main.vert");
  EXPECT_EQ(d[0].line, 3);
  EXPECT_EQ(d[0].column, 1);
  EXPECT_EQ(d[0].message, "something odd");
}

TEST(GlslangLog, FileNameIsTheShortestPrefixBeforeLineAndQuote) {
  // A Windows-style path and a name with ":12" in it: the first ":<digits>: '" ends the file name.
  auto d = parse("ERROR: C:/shaders/a:b.vert:7: 'x' : bad\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].file, "C:/shaders/a:b.vert");
  EXPECT_EQ(d[0].line, 7);
  auto e = parse("ERROR: dir:12x/b.glsl:4: 'y' : bad\n");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].file, "dir:12x/b.glsl");
  EXPECT_EQ(e[0].line, 4);
}

TEST(GlslangLog, TokenRunsToTheFirstQuoteSpaceColon) {
  auto d = parse("ERROR: main.vert:1: 'it's' : quoted ' : twice\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, "'it's' : quoted ' : twice");
}

TEST(GlslangLog, PlainLinesAndFollowUpsAndForeignLines) {
  auto d = parse(
      "ERROR: main.vert:2: 'foo' : undeclared identifier\n"
      "ERROR: main.vert:2: '' : compilation terminated\n"
      "ERROR: 1 compilation errors.  No code generated.\n"
      "ERROR: Linking vertex stage: Missing entry point\n"
      "WARNING: plain warning\r\n"
      "not a glslang line\n"
      "ERROR: main.vert:x: 'foo' : no line number\n");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].line, 2);
  EXPECT_EQ(d[1].message, "Linking vertex stage: Missing entry point");
  EXPECT_EQ(d[1].file, "main.vert");
  EXPECT_EQ(d[1].line, 0);
  // Without a line number the located form does not apply: the whole rest is the message.
  EXPECT_EQ(d[2].message, "main.vert:x: 'foo' : no line number");
}

TEST(GlslangLog, LineNumberPastIntReadsAsWholeFile) {
  auto d = parse("ERROR: main.vert:99999999999999999999: 'foo' : huge\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].line, 0);
}

}  // namespace
}  // namespace stereoshift

// The HLSL construct known to crash glslang (frontend/known_crashes.h), recognised at file scope only.
#include "transpiler/frontend/known_crashes.h"

namespace stereoshift {
namespace {

TEST(KnownGlslangCrashes, AGlobalNamedLikeAStruct) {
  auto found = knownGlslangCrashTrigger("struct P { float4 x; };\n// float4 P; in a comment\nfloat4 P;\n",
                                        SourceLanguage::Hlsl);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->line, 3);
  EXPECT_EQ(found->column, 8);
  EXPECT_NE(found->what.find("'P'"), std::string::npos);
  EXPECT_TRUE(knownGlslangCrashTrigger("struct Light { float3 d; };\nfloat3 Light[4] : register(b1);\n", SourceLanguage::Hlsl));
  // Not the construct: the struct used as a type, a local of its name, a member, GLSL.
  EXPECT_FALSE(knownGlslangCrashTrigger("struct VSOut { float4 p : SV_Position; };\nVSOut main() { VSOut VSOut; return VSOut; }\n",
                                        SourceLanguage::Hlsl));
  EXPECT_FALSE(knownGlslangCrashTrigger("struct P { float4 P; };\nP p;\n", SourceLanguage::Hlsl));
  EXPECT_FALSE(knownGlslangCrashTrigger("struct P { vec4 x; };\nvec4 P;\n", SourceLanguage::Glsl));
}

}  // namespace
}  // namespace stereoshift
