// The readers of shader text that moved onto the lexer (transpiler/source/lexer.h): the #version
// line, include guards, the bracket limit, HLSL entry-point names, effect blanking and `build`'s
// include scan. Each reads comments, strings, splices and directives as the lexer does, which is
// where the tests below differ from what a line-by-line scan made of them.
#include "cli/build_plan.h"
#include "transpiler/frontend/glsl_version.h"
#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/frontend/include_resolver.h"
#include "transpiler/frontend/source_limits.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace stereoshift {
namespace {

TEST(VersionLine, ReadsNumberAndProfile) {
  VersionLine v = findVersion("// header\n#version 300 es\nvoid main() {}\n");
  EXPECT_EQ(v.version, 300);
  EXPECT_TRUE(v.es);
  EXPECT_EQ(v.begin, 10u);
  EXPECT_EQ(v.end, 25u);
  EXPECT_TRUE(v.problem.empty());
  EXPECT_EQ(findVersion("  #  version 450 core\n").version, 450);
  EXPECT_TRUE(findVersion("#version 100\n").es);
  VersionLine none = findVersion("void main() {}\n");
  EXPECT_EQ(none.version, 110);
  EXPECT_EQ(none.begin, std::string::npos);
}

TEST(VersionLine, GarbledAndUnknownVersionsAreProblems) {
  VersionLine garbled = findVersion("#version 3x0\n");
  EXPECT_EQ(garbled.version, 0);
  EXPECT_EQ(garbled.problem, "'#version 3x0': not a GLSL version");
  EXPECT_EQ(garbled.problemAt, 0u);
  EXPECT_EQ(findVersion("#version\n").problem, "'#version': not a GLSL version");
  VersionLine unknown = findVersion("\n#version 451\n");
  EXPECT_EQ(unknown.problem, "#version 451 is not a GLSL version");
  EXPECT_EQ(unknown.problemAt, 10u);
  EXPECT_EQ(findVersion("#version 12345678901234567890123456\n").problem,
            "#version 123456789012345678901234... is not a GLSL version");
}

// Behaviour of the lexer: a `#version` inside a block comment is none (the line scan took it), a
// byte order mark does not hide it, and a comment between the number and the profile is blank.
TEST(VersionLine, ReadThroughTheLexer) {
  EXPECT_EQ(findVersion("/*\n#version 100\n*/\n#version 330\n").version, 330);
  EXPECT_EQ(findVersion("/* old:\n#version 100\n*/\nvoid main() {}\n").begin, std::string::npos);
  VersionLine bom = findVersion("\xEF\xBB\xBF#version 450\n");
  EXPECT_EQ(bom.version, 450);
  EXPECT_EQ(bom.begin, 3u);
  EXPECT_TRUE(findVersion("#version 300 /* ES */ es\n").es);
}

TEST(IncludeGuard, PragmaOnceAndIfndefDefine) {
  EXPECT_TRUE(hasIncludeGuard("#pragma once\nfloat f();\n"));
  EXPECT_TRUE(hasIncludeGuard("// Common lighting.\n/* v2 */\n#ifndef LIGHTING_H\n#define LIGHTING_H\n#endif\n"));
  EXPECT_TRUE(hasIncludeGuard("#ifndef A_H // guard\n#define A_H 1\n#endif\n"));
  EXPECT_FALSE(hasIncludeGuard("#ifndef A_H\n#define B_H\n#endif\n"));
  EXPECT_FALSE(hasIncludeGuard("float f();\n#pragma once\n"));
  EXPECT_FALSE(hasIncludeGuard("#ifndef A_H\nfloat f();\n#define A_H\n"));
  EXPECT_FALSE(hasIncludeGuard("#pragma once extra\n"));
  EXPECT_FALSE(hasIncludeGuard(""));
}

// Behaviour of the lexer: `# ifndef` with blanks after the `#` is the same directive (the line scan
// wanted `#ifndef ` as written), and a comment between the two lines is blank.
TEST(IncludeGuard, ReadThroughTheLexer) {
  EXPECT_TRUE(hasIncludeGuard("# ifndef COMMON_GLSL\n# define COMMON_GLSL\n#endif\n"));
  EXPECT_TRUE(hasIncludeGuard("#ifndef X\n/* the guard */ #define X\n#endif\n"));
  EXPECT_TRUE(hasIncludeGuard("#  pragma once\n"));
}

TEST(NestingLimit, BracketsPastTheLimitAreLocated) {
  std::string deep = "void f() {\n  x = " + std::string(300, '(') + ";\n}\n";
  auto violation = findNestingViolation(deep);
  ASSERT_TRUE(violation);
  EXPECT_EQ(violation->line, 2);
  EXPECT_EQ(violation->column, 6 + kMaxBracketNesting);
  EXPECT_FALSE(findNestingViolation("// " + std::string(300, '(') + "\n\"" + std::string(300, '[') + "\"\n"));
}

// Behaviour of the lexer: a `//` comment continued by a line splice hides the brackets of its next
// line too, as the compilers read it.
TEST(NestingLimit, SplicedCommentHidesItsSecondLine) {
  EXPECT_FALSE(findNestingViolation("// note \\\n" + std::string(300, '{') + "\n"));
}

TEST(HlslEntry, MentionedFunctions) {
  std::set<std::string> names = mentionedFunctions(
      "float4 helper (float x) { return x; }\n#define CALL(x) call(x)\nfloat4 PSMain() : SV_Target { return helper(1); }\n");
  EXPECT_EQ(names, (std::set<std::string>{"CALL", "PSMain", "call", "helper"}));
}

// Behaviour of the lexer: a function named in a comment or a string is not one the file has (the
// text search took `// main()` for an entry point, and glslang then found no `main`).
TEST(HlslEntry, CommentsAndStringsNameNoEntryPoint) {
  std::string text =
      "// Unlike the GLSL version, there is no main() here.\n"
      "float4 VSMain(float3 p : POSITION) : SV_Position { return float4(p, 1); }\n";
  std::set<std::string> names = mentionedFunctions(text);
  EXPECT_EQ(names.count("main"), 0u);
  EXPECT_EQ(chooseHlslEntry(text, names, Stage::Vertex, ""), "VSMain");
  EXPECT_EQ(chooseHlslEntry(text, names, Stage::Vertex, "Other"), "Other");
}

TEST(EffectBlanking, TechniquesAndStateBlocksBecomeBlanks) {
  std::string text = "float4 PS() : SV_Target { return 1; }\ntechnique11 T {\n  pass P { SetPixelShader(CompileShader(ps_5_0, PS())); }\n}\n";
  std::string blanked = blankEffectBlocks(text);
  EXPECT_EQ(blanked.size(), text.size());
  EXPECT_EQ(blanked.find("technique11"), std::string::npos);
  EXPECT_EQ(std::count(blanked.begin(), blanked.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
  EXPECT_EQ(techniqueEntryPoints(text), (std::vector<std::pair<Stage, std::string>>{{Stage::Fragment, "PS"}}));
}

// Behaviour of the lexer: a directive after a comment at the start of its line is a directive (the
// effect scanner took its `{` for code, and left the technique after it unblanked).
TEST(EffectBlanking, DirectiveAfterACommentIsADirective) {
  std::string text = "/* braces */ #define OPEN {\ntechnique11 T { pass P {} }\n";
  EXPECT_EQ(blankEffectBlocks(text).find("technique11"), std::string::npos);
}

class IncludeScan : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("stereoshift_include_scan_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "include");
    for (const char* name : {"a.glsl", "b.glsl", "include/c.glsl", "commented.glsl"}) std::ofstream(dir_ / name) << "\n";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::vector<std::string> scan(const std::string& text) {
    std::vector<std::string> names;
    for (const auto& p : includedFiles(dir_ / "shader.frag", text, {})) names.push_back(p.filename().string());
    return names;
  }
  std::filesystem::path dir_;
};

TEST_F(IncludeScan, QuotedAndAngledIncludesUnderAnyIf) {
  EXPECT_EQ(scan("#include \"a.glsl\"\n#if 0\n  #  include <b.glsl>\n#endif\n#include \"c.glsl\"\n#include \"missing.glsl\"\n"),
            (std::vector<std::string>{"a.glsl", "b.glsl", "c.glsl"}));
}

// Behaviour of the lexer: an #include in a block comment is no dependency (glslang never reads it).
TEST_F(IncludeScan, CommentedIncludeIsNoDependency) {
  EXPECT_EQ(scan("/*\n#include \"commented.glsl\"\n*/\n#include \"a.glsl\"\n"), (std::vector<std::string>{"a.glsl"}));
}

}  // namespace
}  // namespace stereoshift
