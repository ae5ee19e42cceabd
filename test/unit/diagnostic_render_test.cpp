// renderDiagnostics (cli/diagnostic_output.h): which lines get a source line and a caret, and that
// every other line passes through byte for byte.
#include "cli/diagnostic_output.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace stereoshift {
namespace {

class DiagnosticRenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() / ("render_test_" + std::to_string(::getpid()) + ".vert")).string();
    std::ofstream(path_) << "#version 330\r\nvoid main() {\n  gl_Position = vec4(q);\n}\n";
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_;
};

TEST_F(DiagnosticRenderTest, LocatedMessageGetsItsLineAndACaret) {
  std::string text = path_ + ":3:22: error: 'q' : undeclared identifier\n";
  EXPECT_EQ(renderDiagnostics(text, {}), text + "  gl_Position = vec4(q);\n                     ^\n");
}

TEST_F(DiagnosticRenderTest, CarriageReturnOfACrlfLineIsNotShown) {
  std::string text = path_ + ":1:10: error: bad version\n";
  EXPECT_EQ(renderDiagnostics(text, {}), text + "#version 330\n         ^\n");
}

TEST_F(DiagnosticRenderTest, NoCaretWhereTheLocationDoesNotFitTheFile) {
  for (std::string located : {":9:1: error: past the last line\n", ":3:40: error: past the line's end\n",
                              ":3: error: no column\n", ":0:0: error: no line\n"}) {
    std::string text = path_ + located;
    EXPECT_EQ(renderDiagnostics(text, {}), text) << located;
  }
  std::string missing = "/nonexistent/dir/a.vert:1:1: error: cannot read\n";
  EXPECT_EQ(renderDiagnostics(missing, {}), missing);
}

TEST_F(DiagnosticRenderTest, OtherLinesPassThroughUnchanged) {
  std::string text =
      "1 error generated.\nstereoshift: error: no input file\n  a note's continuation: error: not a location\n"
      "\r[====] 3/10 pipelines x\x1b[K\npartial";
  EXPECT_EQ(renderDiagnostics(text, {}), text);
  EXPECT_EQ(renderDiagnostics(text, {false, false}), text);
}

TEST_F(DiagnosticRenderTest, TheFirstSeverityWordSplitsTheLine) {
  // A message that quotes another located message is placed by its own location.
  std::string text = path_ + ":3:3: warning: glslang said 'x.vert:9:9: error: y'\n";
  EXPECT_EQ(renderDiagnostics(text, {}), text + "  gl_Position = vec4(q);\n  ^\n");
}

TEST_F(DiagnosticRenderTest, ColourMarksLocationSeverityAndCaret) {
  std::string text = path_ + ":3:3: note: here\n";
  std::string shown = renderDiagnostics(text, {true, true});
  EXPECT_EQ(shown, "\x1b[1m" + path_ + ":3:3: \x1b[1;36mnote: \x1b[0m\x1b[1mhere\x1b[0m\n  gl_Position = vec4(q);\n  \x1b[1;32m^\x1b[0m\n");
  EXPECT_EQ(renderDiagnostics("plain line\n", {true, true}), "plain line\n");
}

TEST(DiagnosticRender, StandardInputTextIsRemembered) {
  rememberSourceText("<stdin>", "a\nbcd\n");
  EXPECT_EQ(renderDiagnostics("<stdin>:2:3: error: x\n", {}), "<stdin>:2:3: error: x\nbcd\n  ^\n");
}

}  // namespace
}  // namespace stereoshift
