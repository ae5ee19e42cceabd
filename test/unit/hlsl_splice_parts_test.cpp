// Unit tests of the HLSL splice's pieces on their own: the token view (what is a token and what is a
// comment, string or directive, as the lexer reads it), bracket matching, and the edit buffer (edits by offset applied in
// one pass, line endings, where a block of declarations goes), plus the shift's text rendering.
#include "transpiler/backend/hlsl_splice/edit_buffer.h"
#include "transpiler/backend/hlsl_splice/shift_text.h"
#include "transpiler/backend/hlsl_splice/token_view.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace stereoshift::hlsl_splice;

int countOf(const std::string& haystack, const std::string& needle) {
  int n = 0;
  for (size_t p = haystack.find(needle); p != std::string::npos; p = haystack.find(needle, p + needle.size())) ++n;
  return n;
}

std::vector<std::string> tokenTexts(const TokenView& view) {
  std::vector<std::string> out;
  for (size_t k = 0; k < view.tokens.size(); ++k) out.emplace_back(view.text(k));
  return out;
}

TEST(HlslSpliceScanner, CommentsStringsAndDirectivesAreNotTokens) {
  std::string src =
      "#define APPEND(s, v) s.Append(v)\n"
      "// stream.Append(x) in a comment\n"
      "/* block\n comment */ float a = 1.5e-3f; // tail\n"
      "string s = \"Append(\\\"x\\\")\";\n";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  EXPECT_EQ(tokenTexts(view), (std::vector<std::string>{"float", "a", "=", "1.5e-3f", ";", "string", "s", "=",
                                                        "\"Append(\\\"x\\\")\"", ";"}));
  ASSERT_EQ(view.directives.size(), 1u);
  EXPECT_EQ(view.directives[0].name, "define");
  EXPECT_EQ(view.directives[0].macroName, "APPEND");
  EXPECT_EQ(src.substr(view.directives[0].bodyBegin, view.directives[0].end - view.directives[0].bodyBegin),
            " s.Append(v)");
  ASSERT_EQ(view.blockComments.size(), 1u);
  EXPECT_EQ(src.substr(view.blockComments[0].begin, 2), "/*");
  EXPECT_EQ(view.tokens[0].kind, TokKind::Ident);
  EXPECT_EQ(view.tokens[3].kind, TokKind::Number);
  EXPECT_EQ(view.tokens[8].kind, TokKind::String);
}

TEST(HlslSpliceScanner, LineSplicesContinueDirectivesAndComments) {
  std::string src = "#define F(x) \\\n  x.Append(x)\n// comment \\\n still comment\nint b;\n";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  EXPECT_EQ(tokenTexts(view), (std::vector<std::string>{"int", "b", ";"}));
  ASSERT_EQ(view.directives.size(), 1u);
  EXPECT_NE(src.substr(view.directives[0].bodyBegin, view.directives[0].end - view.directives[0].bodyBegin)
                .find("x.Append(x)"),
            std::string::npos);
}

// Read through the lexer: a comment before a #define's name is blank (the old scanner saw no macro
// name), and a `'` on a directive's line is text (`#error don't`), never an open string.
TEST(HlslSpliceScanner, DirectiveLinesAsTheLexerReadsThem) {
  std::string src = "#define /* the helper */ SHIFT(v) v.Append(v)\n#error don't splice\nint b;\n";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  ASSERT_EQ(view.directives.size(), 2u);
  EXPECT_EQ(view.directives[0].macroName, "SHIFT");
  ASSERT_EQ(view.directives[0].body.size(), 6u);  // v . Append ( v )
  EXPECT_EQ(src.substr(view.directives[0].body[2].begin, 6), "Append");
  EXPECT_TRUE(view.directives[0].bodyReadable);
  EXPECT_EQ(view.directives[1].name, "error");
  EXPECT_EQ(view.directives[1].end, src.find('\n', src.find("#error")));
  EXPECT_EQ(tokenTexts(view), (std::vector<std::string>{"int", "b", ";"}));
  // A block comment before a directive on its line leaves the line a directive.
  std::string commentFirst = "/* c */ #define X 1\nint a;\n";
  TokenView after(commentFirst);
  ASSERT_FALSE(after.scan());
  EXPECT_EQ(after.directives.size(), 1u);
}

TEST(HlslSpliceScanner, ByteOrderMarkIsSkipped) {
  std::string src = "\xEF\xBB\xBF" "float4 p;";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  EXPECT_EQ(tokenTexts(view), (std::vector<std::string>{"float4", "p", ";"}));
}

TEST(HlslSpliceScanner, ErrorsCarryTheirOffset) {
  struct Case {
    std::string src;
    size_t offset;
    std::string message;
  };
  std::vector<Case> cases = {
      {"int a; /* open", 7, "unterminated /* comment"},
      {"string s = \"open\n", 11, "unterminated string literal"},
      {"void f() { (] }", 11, "unbalanced '(': closed by ']'"},
      {"void f() }", 9, "unbalanced '}': nothing to close"},
      {"void f() {", 9, "unbalanced '{': never closed"},
  };
  for (const auto& c : cases) {
    TokenView view(c.src);
    auto err = view.scan();
    ASSERT_TRUE(err) << c.src;
    EXPECT_EQ(err->offset, c.offset) << c.src;
    EXPECT_EQ(err->message, c.message) << c.src;
  }
}

TEST(HlslSpliceScanner, BracketsMatchAndLocationsAreOneBased) {
  std::string src = "void f(int a[2])\n{\n  g((a[0]));\n}\n";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  for (size_t k = 0; k < view.tokens.size(); ++k) {
    if (view.match[k] == npos) continue;
    EXPECT_EQ(view.match[view.match[k]], k);
    std::string pair = std::string(view.text(std::min(k, view.match[k]))) +
                       std::string(view.text(std::max(k, view.match[k])));
    EXPECT_TRUE(pair == "()" || pair == "[]" || pair == "{}") << pair;
  }
  EXPECT_EQ(view.skipToSemicolon(0), view.tokens.size());  // a function definition has no ';' at its level
  int line = 0, col = 0;
  view.locate(src.find("g("), line, col);
  EXPECT_EQ(line, 3);
  EXPECT_EQ(col, 3);
  EXPECT_EQ(view.where(0), "1:1");
}

TEST(HlslSpliceEditBuffer, EditsApplyByOffsetInTheOrderAdded) {
  std::string src = "abcdef";
  EditBuffer edits(src);
  edits.add(4, 1, "E");   // replace 'e'
  edits.add(0, 0, "<");
  edits.add(2, 0, "1");
  edits.add(2, 0, "2");   // same offset: after the first
  edits.add(6, 0, ">");
  EXPECT_EQ(edits.apply(), "<ab12cdEf>");
  EXPECT_EQ(src, "abcdef");
  EXPECT_EQ(EditBuffer(src).apply(), src);
}

TEST(HlslSpliceEditBuffer, NewlineIsTheFilesDominantOne) {
  EXPECT_EQ(EditBuffer("a\r\nb\r\nc\n").newline(), "\r\n");
  EXPECT_EQ(EditBuffer("a\nb\nc\r\n").newline(), "\n");
  EXPECT_EQ(EditBuffer("no newline").newline(), "\n");
}

TEST(HlslSpliceEditBuffer, BlockBeforeKeepsCommentsAttachedAndLeavesConditionals) {
  std::string src = "struct S { float4 p : SV_Position; };\n// about f\n// more\nvoid f() {}\n";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  EditBuffer edits(src);
  insertBlockBefore(edits, view, src.find("void"), src.find("\n") + 1, "// X\n");
  EXPECT_EQ(edits.apply(), "struct S { float4 p : SV_Position; };\n// X\n\n// about f\n// more\nvoid f() {}\n");

  std::string cond = "int a;\n#ifdef A\nvoid f() {}\n#endif\n";
  TokenView condView(cond);
  ASSERT_FALSE(condView.scan());
  EXPECT_EQ(insertionBefore(condView, cond.find("void"), 0), std::make_pair(cond.find("#ifdef"), true));
  // Not before `notBefore`: then at the declaration itself, on a line of its own.
  EditBuffer condEdits(cond);
  insertBlockBefore(condEdits, condView, cond.find("void"), cond.find("#ifdef") + 1, "// X\n");
  EXPECT_EQ(condEdits.apply(), "int a;\n#ifdef A\n// X\n\nvoid f() {}\n#endif\n");
}

TEST(HlslSpliceEditBuffer, BlockAfterStartsOnANewLine) {
  std::string src = "void f() {} // end\nint b;";
  TokenView view(src);
  ASSERT_FALSE(view.scan());
  size_t close = 5;  // the '}'
  ASSERT_EQ(view.text(close), "}");
  EditBuffer edits(src);
  insertBlockAfter(edits, view, close, "void g() {}\n");
  EXPECT_EQ(edits.apply(), "void f() {} // end\n\nvoid g() {}\nint b;");

  std::string same = "void f() {} int b;\n";
  TokenView sameView(same);
  ASSERT_FALSE(sameView.scan());
  EditBuffer sameEdits(same);
  insertBlockAfter(sameEdits, sameView, close, "void g() {}\n");
  EXPECT_EQ(sameEdits.apply(), "void f() {}\n\nvoid g() {}\n int b;\n");
}

// The text rendering follows the ShiftSpec: every form the SPIR-V route knows.
TEST(HlslSpliceShiftText, RendersEveryForm) {
  ShiftHelper helper{"VSOut", "stereoshift_shift_VSOut", ".pos"};
  stereoshift::HlslSpliceOptions spec;
  std::string plain = shiftFunctionText(spec, helper, "\n");
  EXPECT_NE(plain.find("    if (eyeSign != 0.0f && abs(stereoshift_v.pos.w - 1.0f) > 9.99999975e-06f && "
                       "!isinf(stereoshift_v.pos.w))\n    {\n        precise float stereoshift_x = stereoshift_v.pos.x + "
                       "(eyeSign * separation) * (stereoshift_v.pos.w - convergence);\n        stereoshift_v.pos.x = "
                       "stereoshift_x;\n    }\n"),
            std::string::npos)
      << plain;

  spec.fused = true;
  std::string fused = shiftFunctionText(spec, helper, "\n");
  EXPECT_NE(fused.find("precise float stereoshift_x = mad(eyeSign * separation, stereoshift_v.pos.w - convergence, "
                       "stereoshift_v.pos.x);"),
            std::string::npos)
      << fused;

  spec.fused = false;
  spec.form = stereoshift::ShiftForm::Select;
  spec.cutoff = stereoshift::CutoffMode::None;
  std::string select = shiftFunctionText(spec, helper, "\n");
  EXPECT_EQ(select.find("if ("), std::string::npos) << select;
  EXPECT_NE(select.find("    stereoshift_v.pos.x = (eyeSign != 0.0f) ? stereoshift_x : stereoshift_v.pos.x;\n"),
            std::string::npos)
      << select;

  spec.form = stereoshift::ShiftForm::Branch;
  spec.compensated = true;
  spec.precise = false;  // the compensated form is `precise` whatever the option says
  std::string compensated = shiftFunctionText(spec, helper, "\n");
  EXPECT_NE(compensated.find("precise float stereoshift_a_c = 4097.0f * stereoshift_a;"), std::string::npos)
      << compensated;
  EXPECT_NE(compensated.find("precise float stereoshift_x = stereoshift_sh + (stereoshift_sl + (stereoshift_pl + "
                             "stereoshift_a * stereoshift_dl));"),
            std::string::npos)
      << compensated;
  EXPECT_EQ(compensated.find("\n        float "), std::string::npos) << compensated;
}

// Halo copies are shifted in the same helper, each from its own x and w; in the select form each
// copy's statements get their own scope, so the compensated form's fixed temporaries never clash.
TEST(HlslSpliceShiftText, ShiftsHaloCopiesInTheSameHelper) {
  ShiftHelper helper{"VSOut", "stereoshift_shift_VSOut", ".pos", {".copy"}};
  stereoshift::HlslSpliceOptions spec;
  std::string plain = shiftFunctionText(spec, helper, "\n");
  EXPECT_NE(plain.find("precise float stereoshift_x1 = stereoshift_v.copy.x + (eyeSign * separation) * "
                       "(stereoshift_v.copy.w - convergence);"),
            std::string::npos)
      << plain;
  EXPECT_LT(plain.find("stereoshift_v.pos.x = stereoshift_x;"), plain.find("stereoshift_v.copy.x = stereoshift_x1;"));

  spec.form = stereoshift::ShiftForm::Select;
  spec.compensated = true;
  std::string select = shiftFunctionText(spec, helper, "\n");
  EXPECT_EQ(countOf(select, "precise float stereoshift_dh = "), 2) << select;
  EXPECT_NE(select.find("    {\n        precise float stereoshift_dh = stereoshift_v.copy.w - convergence;"),
            std::string::npos)
      << select;
}

}  // namespace
