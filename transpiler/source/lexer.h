// The lexer of GLSL and HLSL source text: this turns a shader's bytes into tokens (identifiers,
// numbers, punctuation, string literals, comments and preprocessor directives), each with its byte
// offsets into the original text, its line and column, the directive it sits on and the #if groups
// around it. Every reader of shader text above this layer (language detection, the legacy GLSL
// translation, effect blanking, the version and include-guard readers, the source limits, the
// splices, the stage pragma, the build's include scan) reads through it, so they agree on what is a
// comment, a string or a directive.
//
// The two languages have the same lexical shape, and the lexer reads them alike:
//   - A backslash at the end of a line (before "\n" or "\r\n") splices the next line on: the two are
//     one logical line, a token may run across the splice (`Token::spliced`), and offsets, lines and
//     columns still point into the original text.
//   - `//` comments run to the end of the logical line, `/* */` comments to their close (or to the end
//     of the text: `Token::unterminated`). A comment is one token; its text is no other token.
//   - `"..."` and `'...'` are string literals with backslash escapes; they end at their quote or, left
//     open, before the end of the line (`unterminated`). After `#include`, `<...>` is one too.
//   - A `#` with only blanks and comments before it on its line opens a directive: one Directive token
//     spans the whole logical line, from the `#` to the end of its last line (without the line break),
//     and the tokens of that line follow it, each marked with the directive's kind. Elsewhere `#` is
//     punctuation (a stringizing or pasting operator in a macro body).
//   - Punctuation is one character a token: `::`, `<=`, `[[` are adjacent tokens (one's end is the
//     next one's begin), which is how bracket matching and `=` against `==` read them.
//   - Numbers are preprocessing numbers: a digit, or `.` and a digit, then letters, digits, `_`, `.`
//     and a sign after `e` or `E` (1.5e-3f, 0x1F, 2u, 1.0lf).
//   - A UTF-8 byte order mark at the start of the text is blank.
// Any text lexes: nothing here fails; a client that must refuse an open comment or string asks the
// token. One pass, no allocation per character (a spliced token's spelling is built only when asked).
#pragma once

#include "transpiler/source/identifiers.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stereoshift::source {

enum class TokenKind : uint8_t {
  Identifier,
  Number,
  Punctuation,  // one character
  String,       // with its quotes (or angle brackets)
  Comment,      // with its `//` or `/* */`
  Directive,    // the whole logical line of a preprocessor directive, from its `#`
};

enum class DirectiveKind : uint8_t {
  None,  // the token is on no directive's line
  Version, Extension, Include, Pragma, Define, Undef,
  If, Ifdef, Ifndef, Elif, Else, Endif,
  Line, Error,
  Other,  // any other name (#warning, #import, a line marker `# 1 "file"`), or none (a lone `#`)
};

// The name a directive is spelled with (`Ifdef` -> "ifdef"); "" for None and Other.
const char* directiveKindName(DirectiveKind kind);

struct Token {
  TokenKind kind = TokenKind::Punctuation;
  // A Directive token: which directive. Any other token: the directive whose line it is on, None
  // outside directives (see inDirective).
  DirectiveKind directive = DirectiveKind::None;
  bool unterminated = false;  // a block comment the text ended in, a string the line ended in
  bool spliced = false;       // a backslash-newline runs through it: its spelling is not its bytes
  // #if / #ifdef / #ifndef groups open around the token. A conditional directive (and its line)
  // counts the groups around it: `#if`, its `#elif`s, `#else` and `#endif` are one level out of what
  // they enclose. An #endif with nothing open leaves the depth at 0 (Lexer::unbalancedEndifs).
  uint32_t ifDepth = 0;
  uint32_t line = 1, column = 1;  // of `begin`, 1-based; the column counts bytes
  size_t begin = 0, end = 0;      // [begin, end) in the original text

  bool is(TokenKind k) const { return kind == k; }
  // A token on a directive's line (its name, operands, macro body, comments), not the directive itself.
  bool inDirective() const { return directive != DirectiveKind::None && kind != TokenKind::Directive; }
  // A token of the program text: neither a comment nor a directive or a word on its line.
  bool isCode() const { return kind != TokenKind::Comment && kind != TokenKind::Directive && !inDirective(); }
};

// Pulls the tokens of `text` one at a time: a reader that wants only the start of a file (the first
// #version, an include guard) stops early. `text` must outlive the lexer.
class Lexer {
 public:
  explicit Lexer(std::string_view text);

  // The next token into `token`; false at the end of the text.
  bool next(Token& token);

  // Right after a Directive token: the tokens of its line (its name, operands or macro body),
  // comments left out. The lexer then stands after the line.
  std::vector<Token> directiveWords();

  // #endif directives read so far that closed no group.
  int unbalancedEndifs() const { return unbalancedEndifs_; }
  std::string_view text() const { return text_; }

 private:
  size_t skipSplices(size_t i) const;
  size_t spliceLength(size_t i) const;
  char at(size_t i) const { return i < text_.size() ? text_[i] : '\0'; }
  void countLinesTo(size_t offset);
  bool hasSplice(size_t begin, size_t end) const;
  size_t skipBlanks(size_t i) const;
  size_t lineCommentEnd(size_t i) const;
  size_t blockCommentEnd(size_t i, bool* closed) const;
  size_t quotedEnd(size_t i, char close, bool* closed, bool* spliced) const;
  size_t identifierEnd(size_t i, bool* spliced) const;
  size_t numberEnd(size_t i, bool* spliced) const;
  size_t logicalLineEnd(size_t hash, DirectiveKind kind) const;
  DirectiveKind directiveAt(size_t hash) const;
  void beginDirective(Token& token, size_t hash);

  bool lex(Token& token);

  std::string_view text_;
  size_t pos_ = 0;
  bool peeked_ = false;  // `peek_` is the next token (read past the end of a directive's line)
  Token peek_;
  // Line bookkeeping: the line of offset `counted_`, and where that line starts.
  size_t counted_ = 0;
  uint32_t line_ = 1;
  size_t lineStart_ = 0;
  bool atLineStart_ = true;  // only blanks and comments since the last line break outside tokens
  // The directive being read: its kind and where its logical line ends.
  DirectiveKind directive_ = DirectiveKind::None;
  size_t directiveEnd_ = 0;
  bool expectHeaderName_ = false;  // after `#include`: a `<...>` is a string
  bool sawDirectiveName_ = false;
  uint32_t depth_ = 0;        // #if groups open
  uint32_t directiveDepth_ = 0;  // the depth the tokens of the current directive line carry
  int unbalancedEndifs_ = 0;
};

// Every token of `text`, in order.
std::vector<Token> lex(std::string_view text);

// Whether the token is a `/* */` comment (not a `//` one).
bool isBlockComment(std::string_view text, const Token& t);

// The token's bytes, splices included.
inline std::string_view tokenText(std::string_view text, const Token& t) {
  return text.substr(t.begin, t.end - t.begin);
}

// The token as the compiler reads it: its bytes with every backslash-newline removed. A view of
// `text` when the token has none (the common case), else of `scratch`, which it fills.
std::string_view spelling(std::string_view text, const Token& t, std::string& scratch);
// The same as a string of its own.
std::string spelledString(std::string_view text, const Token& t);

// The backslash-newlines inside the token, in order: appended to a replacement of the token, they
// keep every later line where it was.
std::string splicesOf(std::string_view text, const Token& t);

// Whether `text`, which holds NUL bytes, is still shader source: each NUL is inside a comment or in the
// run of NULs and blanks that ends the text (3Dmigoto writes a NUL after the disassembly in the
// comment that closes a dump; editors and tools pad files with them). A NUL in code is binary.
bool nulsOnlyInCommentsOrAtEnd(std::string_view text);

// The text as a compiler is given it: every NUL byte a space (glslang's preprocessor ends its input at
// the first NUL, even inside a comment). The same string when it holds none.
std::string blankNuls(std::string text);

// 1-based line and byte column of `offset` in `text` (clamped to its end).
std::pair<int, int> lineAndColumn(std::string_view text, size_t offset);

// A whole text lexed, with the questions its readers ask about the tokens by index.
class LexedText {
 public:
  explicit LexedText(std::string_view text) : text_(text), tokens_(lex(text)) {}

  std::string_view text() const { return text_; }
  const std::vector<Token>& tokens() const { return tokens_; }
  size_t size() const { return tokens_.size(); }
  const Token& operator[](size_t k) const { return tokens_[k]; }

  // The bytes of token `k`; empty past the end.
  std::string_view text(size_t k) const { return k < tokens_.size() ? tokenText(text_, tokens_[k]) : std::string_view(); }
  bool isPunct(size_t k, char c) const {
    return k < tokens_.size() && tokens_[k].kind == TokenKind::Punctuation && text_[tokens_[k].begin] == c;
  }
  bool isIdentifier(size_t k) const { return k < tokens_.size() && tokens_[k].kind == TokenKind::Identifier; }
  // Whether tokens k and k+1 are the two characters of `pair` (`::`, `[[`) with nothing between them.
  bool isPunctPair(size_t k, std::string_view pair) const {
    return isPunct(k, pair[0]) && isPunct(k + 1, pair[1]) && tokens_[k].end == tokens_[k + 1].begin;
  }
  // The index of the first token after `k` that is not a comment, or size().
  size_t nextNonComment(size_t k) const;
  // The name of the directive at `k` (a Directive token) as written; "" when it has none.
  std::string_view directiveName(size_t k) const;
  // The first token after directive `k`'s name on its line that is not a comment, or size().
  size_t firstOperand(size_t k) const;
  // One past the last token on directive `k`'s line.
  size_t directiveLineEnd(size_t k) const;

 private:
  std::string_view text_;
  std::vector<Token> tokens_;
};

}  // namespace stereoshift::source
