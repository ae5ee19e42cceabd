// The HLSL splice's view of a file: turns the lexer's tokens (transpiler/source/lexer.h) into what
// the splice reads — the tokens of code (identifiers, numbers, strings, punctuation), the
// preprocessor lines with their macro bodies, the block comments — and pairs up brackets. Comments,
// strings and directive lines are never tokens of code, so nothing inside them is ever rewritten
// (except a #define body's `.Append(`, which the geometry rewriter reads from the directive).
#pragma once

#include "transpiler/source/identifiers.h"

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
  size_t end = 0;    // the end of its logical line (before the line break)
  std::string name;  // "define", "if", "ifdef", "endif", ...
  std::string macroName;
  size_t bodyBegin = 0;     // #define: first offset after the name and the parameter list
  std::vector<Token> body;  // #define: the tokens of the body (comments left out)
  bool bodyReadable = true;  // false: the body holds a string left open
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

std::string lower(std::string_view s);

// SV_Position as a semantic, in any case, with the index 0 that decompilers write (`SV_POSITION0`).
bool isPositionSemantic(std::string_view semantic);

// Matching bracket for every (, [, { and their closers; npos elsewhere.
std::optional<SpliceError> matchBrackets(const std::string& s, const std::vector<Token>& toks,
                                         std::vector<size_t>& match);

// A whole file lexed, with its brackets matched, and the questions the parser and the rewriters
// ask about its tokens.
class TokenView {
 public:
  explicit TokenView(const std::string& source) : s(source) {}

  // Lexes the whole source and matches its brackets. Refused: a block comment or a string left
  // open (a `'` inside a directive's line is text, as in `#error don't`), unbalanced brackets.
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
