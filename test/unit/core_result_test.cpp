// The one result shape above the passes (core/result.h): a value, or a located error that prints as
// every error of the tool does; the assembly reader returns it.
#include "core/result.h"
#include "transpiler/d3dasm/asm_text.h"

#include <gtest/gtest.h>

namespace stereoshift {
namespace {

TEST(CoreResult, AValueOrALocatedError) {
  Result<int> value = 7;
  ASSERT_TRUE(value);
  EXPECT_EQ(*value, 7);
  Result<int> failed = errorAt(3, 14, "unbalanced brackets");
  ASSERT_FALSE(failed);
  EXPECT_EQ(located(failed.error(), "shader.txt").format(), "shader.txt:3:14: error: unbalanced brackets");
  // A file the error names already is kept.
  EXPECT_EQ(located(Diagnostic{Severity::Error, "inc.h", 1, 1, "x"}, "shader.txt").file, "inc.h");
}

TEST(CoreResult, AStatusIsDoneOrAFileError) {
  Status done = Done{};
  EXPECT_TRUE(done);
  Status failed = plainError("cannot write 'out/a.vert'");
  ASSERT_FALSE(failed);
  // A whole-file error prints without a line: `file: error: message`.
  EXPECT_EQ(located(failed.error(), "out/a.vert").format(), "out/a.vert: error: cannot write 'out/a.vert'");
}

TEST(CoreResult, TheAssemblyReaderSaysWhereTheTextIsNotAssembly) {
  Result<d3dasm::AsmText> text = d3dasm::parseAssembly("vs_5_0\nmov o0.xyzw, v0.xy(zw\nret\n");
  ASSERT_FALSE(text);
  EXPECT_EQ(text.error().line, 2);
  EXPECT_GT(text.error().column, 0);
  EXPECT_EQ(located(text.error(), "a-vs.txt").format().rfind("a-vs.txt:2:", 0), 0u) << text.error().format();
  Result<d3dasm::AsmText> none = d3dasm::parseAssembly("// nothing but a comment\n");
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().line, 0);  // the whole file
  Result<d3dasm::AsmText> ok = d3dasm::parseAssembly("vs_4_0\nret\n");
  ASSERT_TRUE(ok) << ok.error().format();
  EXPECT_EQ(ok->lines.size(), 2u);
}

}  // namespace
}  // namespace stereoshift
