// Unit tests of the source-text layer's lexer (transpiler/source/lexer.h): what is a comment, a
// string, a directive and a token; line splices; #if depth; offsets and line:col into the original
// text, CRLF included; GLSL and HLSL samples written in the conventions shaders out there use.
#include "transpiler/source/lexer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace stereoshift::source {
namespace {

// "kind:text" of every token, comments included, directive lines' tokens marked with '@'.
std::vector<std::string> shapes(const std::string& text) {
  std::vector<std::string> out;
  for (const Token& t : lex(text)) {
    std::string kind;
    switch (t.kind) {
      case TokenKind::Identifier: kind = "id"; break;
      case TokenKind::Number: kind = "num"; break;
      case TokenKind::Punctuation: kind = "p"; break;
      case TokenKind::String: kind = "str"; break;
      case TokenKind::Comment: kind = "com"; break;
      case TokenKind::Directive: kind = std::string("#") + directiveKindName(t.directive); break;
    }
    out.push_back((t.inDirective() ? "@" : "") + kind + ":" + std::string(tokenText(text, t)));
  }
  return out;
}

std::vector<std::string> spellings(const std::string& text, TokenKind kind) {
  std::vector<std::string> out;
  for (const Token& t : lex(text))
    if (t.kind == kind) out.push_back(spelledString(text, t));
  return out;
}

const Token& only(const std::vector<Token>& tokens, TokenKind kind) {
  for (const Token& t : tokens)
    if (t.kind == kind) return t;
  static Token none;
  ADD_FAILURE() << "no token of that kind";
  return none;
}

TEST(SourceLexer, LineAndBlockComments) {
  EXPECT_EQ(shapes("a // b c\nd /* e\nf */ g"),
            (std::vector<std::string>{"id:a", "com:// b c", "id:d", "com:/* e\nf */", "id:g"}));
  // A comment is one token: no other comment, string or directive starts inside it.
  EXPECT_EQ(shapes("/* // \" #define */x // /* \"\n#y"),
            (std::vector<std::string>{"com:/* // \" #define */", "id:x", "com:// /* \"", "#:#y", "@id:y"}));
}

TEST(SourceLexer, BlockCommentsDoNotNest) {
  // The first `*/` closes the comment, as in C and both shader languages.
  EXPECT_EQ(shapes("/* a /* b */ c */"),
            (std::vector<std::string>{"com:/* a /* b */", "id:c", "p:*", "p:/"}));
  EXPECT_EQ(shapes("/*/ x */y"), (std::vector<std::string>{"com:/*/ x */", "id:y"}));
}

TEST(SourceLexer, UnterminatedCommentRunsToTheEnd) {
  std::string text = "float a; /* open\nfloat b;";
  std::vector<Token> tokens = lex(text);
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens.back().kind, TokenKind::Comment);
  EXPECT_TRUE(tokens.back().unterminated);
  EXPECT_EQ(tokens.back().end, text.size());
  EXPECT_TRUE(isBlockComment(text, tokens.back()));
  EXPECT_FALSE(tokens[0].unterminated);
}

TEST(SourceLexer, StringsWithEscapes) {
  EXPECT_EQ(shapes(R"(s = "a\"b // not a comment"; c = 'x';)"),
            (std::vector<std::string>{"id:s", "p:=", R"(str:"a\"b // not a comment")", "p:;", "id:c", "p:=",
                                      "str:'x'", "p:;"}));
  EXPECT_EQ(spellings(R"("\\" x "")", TokenKind::String), (std::vector<std::string>{R"("\\")", R"("")"}));
}

TEST(SourceLexer, UnterminatedStringEndsWithItsLine) {
  std::string text = "\"open\r\nx \"closed\"";
  std::vector<Token> tokens = lex(text);
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_TRUE(tokens[0].unterminated);
  EXPECT_EQ(tokenText(text, tokens[0]), "\"open");  // neither the '\r' nor the line break
  EXPECT_EQ(tokens[1].line, 2u);
  EXPECT_FALSE(tokens[2].unterminated);
}

TEST(SourceLexer, SplicedIdentifierIsOneToken) {
  std::string text = "int ma\\\nin = 1;";
  std::vector<Token> tokens = lex(text);
  ASSERT_EQ(tokens.size(), 5u);
  const Token& name = tokens[1];
  EXPECT_EQ(name.kind, TokenKind::Identifier);
  EXPECT_TRUE(name.spliced);
  EXPECT_EQ(tokenText(text, name), "ma\\\nin");  // the bytes, splice included
  EXPECT_EQ(spelledString(text, name), "main");  // as the compiler reads it
  EXPECT_EQ(splicesOf(text, name), "\\\n");
  EXPECT_EQ(name.begin, 4u);
  EXPECT_EQ(name.end, 10u);
  EXPECT_EQ(name.line, 1u);
  EXPECT_EQ(tokens[2].line, 2u);  // `=`: on the second physical line
  EXPECT_EQ(tokens[2].column, 4u);
  EXPECT_FALSE(tokens[0].spliced);
  // A splice with a CRLF line end, inside a number.
  std::string crlf = "x = 1\\\r\n5;";
  EXPECT_EQ(spellings(crlf, TokenKind::Number), (std::vector<std::string>{"15"}));
}

TEST(SourceLexer, SplicedDirectiveIsOneLogicalLine) {
  std::string text = "#define ADD(a, b) \\\n    ((a) + (b))\nint x;";
  std::vector<Token> tokens = lex(text);
  ASSERT_EQ(tokens[0].kind, TokenKind::Directive);
  EXPECT_EQ(tokens[0].directive, DirectiveKind::Define);
  EXPECT_EQ(tokenText(text, tokens[0]), "#define ADD(a, b) \\\n    ((a) + (b))");
  size_t inDirective = 0;
  for (const Token& t : tokens) {
    if (!t.inDirective()) continue;
    ++inDirective;
    EXPECT_EQ(t.directive, DirectiveKind::Define);
  }
  EXPECT_EQ(inDirective, 16u);  // define ADD ( a , b ) ( ( a ) + ( b ) )
  const Token& last = tokens[tokens.size() - 3];
  EXPECT_EQ(tokenText(text, last), "int");
  EXPECT_FALSE(last.inDirective());
  EXPECT_EQ(last.line, 3u);
  // The directive's name may be split too.
  EXPECT_EQ(lex("#def\\\nine X 1")[0].directive, DirectiveKind::Define);
}

TEST(SourceLexer, SplicedLineCommentGoesOn) {
  EXPECT_EQ(shapes("// one \\\n two\nthree"), (std::vector<std::string>{"com:// one \\\n two", "id:three"}));
  std::vector<Token> tokens = lex("// a \\\r\n b\r\nc");
  EXPECT_TRUE(tokens[0].spliced);
  EXPECT_EQ(tokens[1].line, 3u);
  // A splice between `*` and `/` still closes a block comment.
  EXPECT_EQ(shapes("/* x *\\\n/y"), (std::vector<std::string>{"com:/* x *\\\n/", "id:y"}));
}

TEST(SourceLexer, EveryDirectiveKind) {
  std::string text =
      "#version 450 core\n#extension GL_EXT_x : enable\n#include \"a.glsl\"\n#pragma once\n#define A 1\n"
      "#undef A\n#if A\n#ifdef B\n#ifndef C\n#elif D\n#else\n#endif\n#endif\n#endif\n#line 10\n#error stop\n"
      "#warning w\n#\n";
  std::vector<DirectiveKind> kinds;
  for (const Token& t : lex(text))
    if (t.kind == TokenKind::Directive) kinds.push_back(t.directive);
  using D = DirectiveKind;
  EXPECT_EQ(kinds, (std::vector<D>{D::Version, D::Extension, D::Include, D::Pragma, D::Define, D::Undef, D::If,
                                   D::Ifdef, D::Ifndef, D::Elif, D::Else, D::Endif, D::Endif, D::Endif, D::Line,
                                   D::Error, D::Other, D::Other}));
  EXPECT_STREQ(directiveKindName(D::Ifndef), "ifndef");
  EXPECT_STREQ(directiveKindName(D::Other), "");
}

TEST(SourceLexer, DirectivesWithBlanksAndComments) {
  std::string text = "   #  define X 1\n\t# if X\n/* c */ #endif\nint y; # not a directive\n";
  EXPECT_EQ(shapes(text),
            (std::vector<std::string>{"#define:#  define X 1", "@id:define", "@id:X", "@num:1", "#if:# if X",
                                      "@id:if", "@id:X", "com:/* c */", "#endif:#endif", "@id:endif", "id:int",
                                      "id:y", "p:;", "p:#", "id:not", "id:a", "id:directive"}));
  LexedText lexed(text);
  EXPECT_EQ(lexed.directiveName(0), "define");
  EXPECT_EQ(lexed.text(lexed.firstOperand(0)), "X");
  EXPECT_EQ(lexed.directiveLineEnd(0), 4u);
  EXPECT_EQ(lexed[0].column, 4u);
  // `#` inside a macro body is an operator, not a directive.
  EXPECT_EQ(shapes("#define S(x) #x\n"),
            (std::vector<std::string>{"#define:#define S(x) #x", "@id:define", "@id:S", "@p:(", "@id:x", "@p:)",
                                      "@p:#", "@id:x"}));
}

TEST(SourceLexer, IncludeHeaderNameIsOneString) {
  EXPECT_EQ(shapes("#include <shaders/common.glsl> // c\n#include\"local.h\"\nx < y > z"),
            (std::vector<std::string>{"#include:#include <shaders/common.glsl> // c", "@id:include",
                                      "@str:<shaders/common.glsl>", "@com:// c", "#include:#include\"local.h\"",
                                      "@id:include", "@str:\"local.h\"", "id:x", "p:<", "id:y", "p:>", "id:z"}));
}

TEST(SourceLexer, IncludeWithoutAHeaderLeavesLaterAnglesAlone) {
  // `#include` alone on its line (a half-edited file, a fuzzer's mutation): the `<` of a later loop
  // is an operator. It used to be read as a header name ending at the directive's old line end,
  // before its own start, and the lexer went back and read the same text for ever.
  EXPECT_EQ(shapes("#include\nfor (i = 0; i < 4; ++i) x;"),
            (std::vector<std::string>{"#include:#include", "@id:include", "id:for", "p:(", "id:i", "p:=", "num:0",
                                      "p:;", "id:i", "p:<", "num:4", "p:;", "p:+", "p:+", "id:i", "p:)", "id:x",
                                      "p:;"}));
}

TEST(SourceLexer, IfNestingDepth) {
  std::string text =
      "a\n#if A\nb\n#ifdef B\nc\n#elif C\nd\n#else\ne\n#endif\nf\n#endif\ng\n";
  std::vector<std::pair<std::string, uint32_t>> depths;
  for (const Token& t : lex(text)) {
    if (t.inDirective()) continue;
    std::string what = t.kind == TokenKind::Directive ? std::string("#") + directiveKindName(t.directive)
                                                      : std::string(tokenText(text, t));
    depths.push_back({what, t.ifDepth});
  }
  EXPECT_EQ(depths, (std::vector<std::pair<std::string, uint32_t>>{
                        {"a", 0}, {"#if", 0}, {"b", 1}, {"#ifdef", 1}, {"c", 2}, {"#elif", 1}, {"d", 2},
                        {"#else", 1}, {"e", 2}, {"#endif", 1}, {"f", 1}, {"#endif", 0}, {"g", 0}}));
  // The condition of an #if is read at the #if's own depth.
  LexedText lexed("#if defined(X)\n#endif");
  EXPECT_EQ(lexed[1].ifDepth, 0u);
  EXPECT_EQ(lexed[2].ifDepth, 0u);
}

TEST(SourceLexer, UnbalancedEndifLeavesDepthZero) {
  Lexer lexer("#endif\nx\n#if 1\n#endif\n#endif\ny");
  Token t;
  std::vector<uint32_t> depths;
  while (lexer.next(t))
    if (t.kind == TokenKind::Identifier && !t.inDirective()) depths.push_back(t.ifDepth);
  EXPECT_EQ(depths, (std::vector<uint32_t>{0, 0}));
  EXPECT_EQ(lexer.unbalancedEndifs(), 2);
}

TEST(SourceLexer, CrlfLineEndings) {
  std::string text = "#version 100\r\n// c\r\nattribute vec4 p;\r\n#define X \\\r\n  1\r\nvoid main() {}\r\n";
  LexedText lexed(text);
  EXPECT_EQ(lexed.text(0), "#version 100");  // without the '\r'
  EXPECT_EQ(lexed.text(3), "// c");
  EXPECT_EQ(lexed[4].line, 3u);
  EXPECT_EQ(lexed[4].column, 1u);
  size_t define = 0;
  while (lexed[define].directive != DirectiveKind::Define) ++define;
  EXPECT_EQ(lexed.text(define), "#define X \\\r\n  1");
  size_t main = define;
  while (lexed.text(main) != "main") ++main;
  EXPECT_EQ(lexed[main].line, 6u);
  EXPECT_EQ(lexed[main].column, 6u);
}

TEST(SourceLexer, OffsetsAndLineColumnPointIntoTheOriginal) {
  std::string text = "a\n  bb /* x\n y */ ccc\n";
  std::vector<Token> tokens = lex(text);
  ASSERT_EQ(tokens.size(), 4u);
  for (const Token& t : tokens) {
    auto [line, column] = lineAndColumn(text, t.begin);
    EXPECT_EQ(static_cast<uint32_t>(line), t.line) << tokenText(text, t);
    EXPECT_EQ(static_cast<uint32_t>(column), t.column) << tokenText(text, t);
  }
  EXPECT_EQ(tokens[1].begin, 4u);
  EXPECT_EQ(tokens[1].end, 6u);
  EXPECT_EQ(tokens[3].line, 3u);
  EXPECT_EQ(tokens[3].column, 7u);
  EXPECT_EQ(lineAndColumn(text, 0), std::make_pair(1, 1));
  EXPECT_EQ(lineAndColumn(text, 1000), std::make_pair(4, 1));  // clamped to the end
}

TEST(SourceLexer, ByteOrderMarkIsBlank) {
  std::string text = "\xEF\xBB\xBF#version 450\nvoid main(){}";
  std::vector<Token> tokens = lex(text);
  ASSERT_FALSE(tokens.empty());
  EXPECT_EQ(tokens[0].kind, TokenKind::Directive);  // the mark does not hide the directive
  EXPECT_EQ(tokens[0].begin, 3u);
  EXPECT_EQ(tokens[0].column, 4u);  // columns count bytes
}

TEST(SourceLexer, NumbersAndPunctuation) {
  EXPECT_EQ(spellings("1.5e-3f + 0x1F - .5 * 2u / 1e+5 - 3.0lf; a.b", TokenKind::Number),
            (std::vector<std::string>{"1.5e-3f", "0x1F", ".5", "2u", "1e+5", "3.0lf"}));
  EXPECT_EQ(shapes("a.b<=c"), (std::vector<std::string>{"id:a", "p:.", "id:b", "p:<", "p:=", "id:c"}));
  // Bytes outside ASCII are never part of an identifier.
  EXPECT_EQ(shapes("x\xC3\xA9y"), (std::vector<std::string>{"id:x", "p:\xC3", "p:\xA9", "id:y"}));
}

TEST(SourceLexer, PullLexerStopsWhereAsked) {
  std::string text = "#version 310 es\nprecision mediump float;\n";
  Lexer lexer(text);
  Token t;
  ASSERT_TRUE(lexer.next(t));
  EXPECT_EQ(t.directive, DirectiveKind::Version);
  std::vector<Token> all = lex(text);
  size_t k = 1;
  while (lexer.next(t)) {
    ASSERT_LT(k, all.size());
    EXPECT_EQ(t.begin, all[k].begin);
    EXPECT_EQ(t.end, all[k].end);
    ++k;
  }
  EXPECT_EQ(k, all.size());
  EXPECT_FALSE(lexer.next(t));  // and stays at the end
  EXPECT_TRUE(lex("").empty());
  EXPECT_TRUE(lex(" \n\t\r\n").empty());
}

TEST(SourceLexer, DirectiveWordsReadOneLineAndGiveBackTheNextToken) {
  std::string text = "#pragma /* c */ shader_stage(vertex) // tail\n#\nvoid main();";
  Lexer lexer(text);
  Token t;
  ASSERT_TRUE(lexer.next(t));
  ASSERT_EQ(t.directive, DirectiveKind::Pragma);
  std::vector<std::string> words;
  for (const Token& w : lexer.directiveWords()) words.push_back(std::string(tokenText(text, w)));
  EXPECT_EQ(words, (std::vector<std::string>{"pragma", "shader_stage", "(", "vertex", ")"}));
  ASSERT_TRUE(lexer.next(t));  // the lone `#`: a directive with no words
  EXPECT_EQ(t.kind, TokenKind::Directive);
  EXPECT_TRUE(lexer.directiveWords().empty());
  ASSERT_TRUE(lexer.next(t));  // given back, not lost
  EXPECT_EQ(tokenText(text, t), "void");
}

TEST(SourceLexer, GlslSample) {
  std::string text =
      "#version 300 es\n"
      "// The vertex stage of a textured quad.\n"
      "precision highp float;\n"
      "layout(location = 0) in vec3 position;\n"
      "uniform mat4 u_mvp; /* model-view-projection */\n"
      "#ifdef GL_ES\n"
      "out mediump vec2 v_uv;\n"
      "#endif\n"
      "void main() {\n"
      "  gl_Position = u_mvp * vec4(position, 1.0);\n"
      "}\n";
  LexedText lexed(text);
  std::vector<std::string> code;
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed.isIdentifier(k) && !lexed[k].inDirective()) code.push_back(std::string(lexed.text(k)));
  EXPECT_EQ(code, (std::vector<std::string>{"precision", "highp", "float", "layout", "location", "in", "vec3",
                                            "position", "uniform", "mat4", "u_mvp", "out", "mediump", "vec2",
                                            "v_uv", "void", "main", "gl_Position", "u_mvp", "vec4", "position"}));
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed.text(k) == "v_uv") EXPECT_EQ(lexed[k].ifDepth, 1u);
  EXPECT_EQ(lexed.text(lexed.firstOperand(0)), "300");
  EXPECT_EQ(lexed[0].directive, DirectiveKind::Version);
}

TEST(SourceLexer, HlslEffectSample) {
  std::string text =
      "// An effect file: resources, a vertex shader, a technique.\n"
      "[[vk::binding(0)]] cbuffer Camera : register(b0) { float4x4 viewProj; };\n"
      "struct VSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };\n"
      "VSOut VSMain(float3 p : POSITION) {\n"
      "  VSOut o; o.pos = mul(float4(p, 1), viewProj); o.uv = 0; return o;\n"
      "}\n"
      "technique11 Render {\n"
      "  pass P0 { SetVertexShader(CompileShader(vs_5_0, VSMain())); }\n"
      "}\n";
  LexedText lexed(text);
  size_t open = 0;
  while (!lexed.isPunct(open, '[')) ++open;
  EXPECT_TRUE(lexed.isPunctPair(open, "[["));
  EXPECT_EQ(lexed.text(open + 2), "vk");
  EXPECT_TRUE(lexed.isPunctPair(open + 3, "::"));
  EXPECT_EQ(lexed.text(open + 5), "binding");
  EXPECT_FALSE(lexed.isPunctPair(open + 2, "::"));
  std::vector<std::string> afterColon;  // what each `:` introduces: a register or a semantic
  for (size_t k = 0; k + 1 < lexed.size(); ++k)
    if (lexed.isPunct(k, ':') && !lexed.isPunctPair(k, "::") && !(k > 0 && lexed.isPunctPair(k - 1, "::")))
      afterColon.push_back(std::string(lexed.text(k + 1)));
  EXPECT_EQ(afterColon, (std::vector<std::string>{"register", "SV_Position", "TEXCOORD0", "POSITION"}));
  size_t technique = 0;
  while (lexed.text(technique) != "technique11") ++technique;
  EXPECT_EQ(lexed[technique].kind, TokenKind::Identifier);
  EXPECT_EQ(lexed[technique].line, 7u);
  EXPECT_EQ(lexed[technique].column, 1u);
  EXPECT_EQ(spellings(text, TokenKind::Comment).size(), 1u);
}

// NUL bytes: text where each is in a comment or in the run of NULs and blanks that ends the file.
TEST(SourceLexer, NulsInCommentsOrAtTheEndAreText) {
  using namespace std::string_literals;
  EXPECT_TRUE(nulsOnlyInCommentsOrAtEnd("void main() {}\n/* disassembly\n\0\n*/\n"s));
  EXPECT_TRUE(nulsOnlyInCommentsOrAtEnd("void main() {} // a\0b\n"s));
  EXPECT_TRUE(nulsOnlyInCommentsOrAtEnd("void main() {}\n\0\0\n\0"s));
  EXPECT_TRUE(nulsOnlyInCommentsOrAtEnd("void main() {}\n"s));
  EXPECT_FALSE(nulsOnlyInCommentsOrAtEnd("void main() {\0}\n"s));
  EXPECT_FALSE(nulsOnlyInCommentsOrAtEnd("\0void main() {}\n"s));
  EXPECT_FALSE(nulsOnlyInCommentsOrAtEnd("/* a */\0 x\n"s));
  EXPECT_FALSE(nulsOnlyInCommentsOrAtEnd("float s = \"\0\";\n"s));
  EXPECT_EQ(blankNuls("a\0b\0"s), "a b ");
}

}  // namespace
}  // namespace stereoshift::source
