// The HLSL splice's scanner: turns source text into tokens (identifiers, numbers, strings,
// punctuation), the preprocessor lines and the block comments between them, and pairs up brackets.
// Comments, strings and directives are never tokens, so nothing inside them is ever rewritten.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stereoshift::hlsl_splice {

constexpr size_t npos = std::string::npos;

enum class TokKind { Ident, Number, String, Punct };

struct Token {
  TokKind kind;
  size_t begin;
  size_t end;
};

struct Directive {
  size_t begin = 0;  // offset of '#'
  size_t end = 0;    // offset of the terminating newline (or end of text)
  std::string name;  // "define", "if", "ifdef", "endif", ...
  std::string macroName;
  size_t bodyBegin = 0;  // #define: first offset after the name and the parameter list
};

struct Span {
  size_t begin, end;
};

struct SpliceError {
  size_t offset;  // npos: no location
  std::string message;
  // A clash with the source (a name or the register already taken) that no route resolves, as
  // opposed to text the splice does not read.
  bool clash = false;
};

bool isIdentStart(char c);
std::string lower(std::string_view s);
bool isValidIdentifier(const std::string& s);

class Scanner {
 public:
  // Scans [begin, end) of `src`. `directives`: recognise preprocessor lines (false when scanning
  // the body of a #define, where '#' is the stringizing operator).
  Scanner(const std::string& src, size_t begin, size_t end, bool directives)
      : s_(src), begin_(begin), end_(end), directives_(directives) {}

  std::optional<SpliceError> run();

  std::vector<Token> tokens;
  std::vector<Directive> directivesList;
  std::vector<Span> blockComments;

 private:
  char at(size_t i) const { return i < end_ ? s_[i] : '\0'; }
  size_t lineSplice(size_t i) const;
  size_t lineCommentEnd(size_t i) const;
  std::optional<SpliceError> directive(size_t hash);

  const std::string& s_;
  size_t begin_, end_;
  bool directives_;
};

// Matching bracket for every (, [, { and their closers; npos elsewhere.
std::optional<SpliceError> matchBrackets(const std::string& s, const std::vector<Token>& toks,
                                         std::vector<size_t>& match);

// A whole file scanned, with its brackets matched, and the questions the parser and the rewriters
// ask about its tokens.
class TokenView {
 public:
  explicit TokenView(const std::string& source) : s(source) {}

  // Scans the whole source and matches its brackets.
  std::optional<SpliceError> scan();

  std::string_view text(size_t k) const {
    return std::string_view(s).substr(tokens[k].begin, tokens[k].end - tokens[k].begin);
  }
  bool isPunct(size_t k, char c) const {
    return k < tokens.size() && tokens[k].kind == TokKind::Punct && s[tokens[k].begin] == c;
  }
  bool isIdent(size_t k) const { return k < tokens.size() && tokens[k].kind == TokKind::Ident; }
  bool isWord(size_t k, std::string_view w) const { return isIdent(k) && text(k) == w; }
  std::string tokSpan(size_t first, size_t last) const {  // inclusive token range, verbatim
    return s.substr(tokens[first].begin, tokens[last].end - tokens[first].begin);
  }
  SpliceError errAt(size_t tok, std::string msg) const { return {tokens[tok].begin, std::move(msg)}; }

  // 1-based line and byte column of `offset`.
  void locate(size_t offset, int& line, int& col) const;
  std::string where(size_t offset) const;  // "line:col"

  // Index of the ';' ending the declaration starting at k (brackets skipped), or the '}' that
  // closes the enclosing scope, or the token count.
  size_t skipToSemicolon(size_t k) const;

  const std::string& s;
  std::vector<Token> tokens;
  std::vector<Directive> directives;
  std::vector<Span> blockComments;
  std::vector<size_t> match;
};

}  // namespace stereoshift::hlsl_splice
