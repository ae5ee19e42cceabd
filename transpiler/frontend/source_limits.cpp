// This turns shader source text into the first place it goes past one of the front end's text
// limits (see source_limits.h): brackets, statement nesting, operator runs; with its line and
// column, in passes over the lexer's tokens that are linear in the text.
#include "transpiler/frontend/source_limits.h"

#include "transpiler/source/lexer.h"

#include <cstdio>
#include <string_view>
#include <vector>

namespace stereoshift {

namespace {

LimitViolation violationAt(const source::Token& t, std::string message) {
  LimitViolation v;
  v.line = static_cast<int>(t.line);
  v.column = static_cast<int>(t.column);
  v.message = std::move(message);
  return v;
}

bool isPunct(const std::string& text, const source::Token& t, char c) {
  return t.kind == source::TokenKind::Punctuation && text[t.begin] == c;
}

bool isWord(const std::string& text, const source::Token& t, std::string_view word) {
  return t.kind == source::TokenKind::Identifier && std::string_view(text).substr(t.begin, t.end - t.begin) == word;
}

// Statement nesting, read from the tokens as the grammar nests statements: an `if`, `for`,
// `while` or `switch` (after its parenthesised head) or a `do` opens a level around its body, a
// braced block or one statement; the level closes when the body ends, except that an `if` whose
// body ended takes its `else` (so an `else if` chain nests, as it does in SPIR-V) and a `do` its
// `while (...);`. glslang's HLSL parser is quadratic in this nesting (20,000 levels took most of a
// minute) before any tree exists to check, hence a check on the text.
std::optional<LimitViolation> findStatementNestingViolation(const std::string& text,
                                                            const std::vector<source::Token>& code) {
  struct Level {
    bool isIf = false, isDo = false;
    bool braced = false;      // the body is a `{ ... }` block
    int braceDepth = 0;       // braced: the depth inside its `{`; else: the depth of its statement
    bool bodyDone = false;    // a `do` whose body ended, waiting for `while (...) ;`
  };
  std::vector<Level> open;
  int braceDepth = 0;
  // Skips a parenthesised head starting at `k` (a `(`); returns the index after its `)`.
  auto skipParens = [&](size_t k) {
    int depth = 0;
    for (; k < code.size(); ++k) {
      if (isPunct(text, code[k], '(')) ++depth;
      if (isPunct(text, code[k], ')') && --depth == 0) return k + 1;
    }
    return k;
  };
  // A statement ended at `k` (its `;` or its block's `}`): the single-statement bodies it was, close,
  // and so on outwards; an `if` followed by `else`, or a `do` followed by `while`, stays open.
  auto statementEnded = [&](size_t k) {
    while (!open.empty() && !open.back().braced && open.back().braceDepth == braceDepth) {
      Level& top = open.back();
      size_t next = k + 1;
      if (top.isIf && next < code.size() && isWord(text, code[next], "else")) return;
      if (top.isDo && !top.bodyDone) {
        top.bodyDone = true;
        return;
      }
      open.pop_back();
    }
  };
  auto opens = [&](size_t keyword, size_t bodyStart, bool isIf, bool isDo) -> std::optional<LimitViolation> {
    Level level;
    level.isIf = isIf;
    level.isDo = isDo;
    level.braced = bodyStart < code.size() && isPunct(text, code[bodyStart], '{');
    level.braceDepth = level.braced ? braceDepth + 1 : braceDepth;
    open.push_back(level);
    if (static_cast<int>(open.size()) > kMaxControlFlowNesting) return violationAt(code[keyword], controlFlowNestingMessage());
    return std::nullopt;
  };
  for (size_t k = 0; k < code.size();) {
    const source::Token& t = code[k];
    bool doWhile = !open.empty() && open.back().isDo && open.back().bodyDone && isWord(text, t, "while");
    if (doWhile) {
      k = skipParens(k + 1);  // then its `;` ends the do statement
      open.back().isDo = false;
      continue;
    }
    if (isWord(text, t, "if") || isWord(text, t, "for") || isWord(text, t, "while") || isWord(text, t, "switch")) {
      size_t body = skipParens(k + 1);
      if (auto v = opens(k, body, isWord(text, t, "if"), false)) return v;
      k = body;
      if (k < code.size() && isPunct(text, code[k], '{')) ++braceDepth, ++k;
      continue;
    }
    if (isWord(text, t, "do")) {
      if (auto v = opens(k, k + 1, false, true)) return v;
      ++k;
      if (k < code.size() && isPunct(text, code[k], '{')) ++braceDepth, ++k;
      continue;
    }
    if (isWord(text, t, "else")) {
      // The open `if` it belongs to keeps its level: its else body is the rest of it.
      if (!open.empty() && open.back().isIf) {
        open.back().isIf = false;  // one else per if
        open.back().braced = k + 1 < code.size() && isPunct(text, code[k + 1], '{');
        open.back().braceDepth = open.back().braced ? braceDepth + 1 : braceDepth;
      }
      ++k;
      if (k < code.size() && isPunct(text, code[k], '{')) ++braceDepth, ++k;
      continue;
    }
    if (isPunct(text, t, '{')) {
      ++braceDepth;
    } else if (isPunct(text, t, '}')) {
      if (braceDepth > 0) --braceDepth;
      // A braced body closing ends its level's statement; an unbraced one left open inside a block
      // that closes (malformed text) closes with it.
      while (!open.empty() && open.back().braceDepth > braceDepth) {
        bool braced = open.back().braced;
        if (braced && open.back().braceDepth == braceDepth + 1) {
          Level& top = open.back();
          top.braced = false;
          top.braceDepth = braceDepth;
          if (top.isIf && k + 1 < code.size() && isWord(text, code[k + 1], "else")) break;
          if (top.isDo) {
            top.bodyDone = true;
            break;
          }
          open.pop_back();
          statementEnded(k);
          break;
        }
        open.pop_back();
      }
    } else if (isPunct(text, t, ';')) {
      statementEnded(k);
    }
    ++k;
  }
  return std::nullopt;
}

// The longest run of operators of one expression at one bracket level: `y * y * ... * y` is a tree
// as deep as the run is long, and glslang builds and walks such trees by recursion: 100,000 terms
// overflowed its stack while parsing, before the syntax-tree limit could be checked on the tree.
// Counted: the operator characters (+ - * / % < > = ! & | ^ ?) between `,`, `;`, `:` and brackets
// at one level; a run past kMaxSyntaxTreeDepth is refused at the operator that passes it.
std::optional<LimitViolation> findOperatorRunViolation(const std::string& text, const std::vector<source::Token>& code) {
  std::vector<int> runs = {0};
  for (const source::Token& t : code) {
    if (t.kind != source::TokenKind::Punctuation) continue;
    char c = text[t.begin];
    switch (c) {
      case '(': case '[': case '{': runs.push_back(0); break;
      case ')': case ']': case '}': if (runs.size() > 1) runs.pop_back(); break;
      case ',': case ';': case ':': runs.back() = 0; break;
      case '+': case '-': case '*': case '/': case '%': case '<': case '>': case '=': case '!':
      case '&': case '|': case '^': case '?':
        if (++runs.back() > kMaxSyntaxTreeDepth)
          return violationAt(t, "this expression chains more than " + std::to_string(kMaxSyntaxTreeDepth) +
                                    " operators at one level (the front end's limit: glslang builds and walks "
                                    "expression trees by recursion); split it with temporaries");
        break;
      default: break;
    }
  }
  return std::nullopt;
}

}  // namespace

std::string controlFlowNestingMessage() {
  return "control flow (if, ?:, loops, switch) nests deeper than " + std::to_string(kMaxControlFlowNesting) +
         " levels here (the front end's limit: SPIR-V validation time grows with the cube of it)";
}

std::optional<LimitViolation> findNestingViolation(const std::string& text) {
  // One pass of the lexer: the bracket limit on every punctuation token (directives' brackets are
  // read as their tokens: macro bodies are code), the code tokens kept for the other two scans.
  source::Lexer lexer(text);
  source::Token t;
  std::vector<source::Token> code;
  int depth = 0;
  while (lexer.next(t)) {
    if (t.isCode()) code.push_back(t);
    if (t.kind != source::TokenKind::Punctuation) continue;
    char c = text[t.begin];
    if (c == '(' || c == '[' || c == '{') {
      if (++depth > kMaxBracketNesting)
        return violationAt(t, "brackets nest deeper than " + std::to_string(kMaxBracketNesting) +
                                  " levels here (the front end's limit: glslang parses nested brackets by recursion)");
    } else if ((c == ')' || c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  if (auto v = findStatementNestingViolation(text, code)) return v;
  return findOperatorRunViolation(text, code);
}

std::string describeBytes(size_t bytes) {
  char buffer[32];
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0)
    std::snprintf(buffer, sizeof buffer, "%zu MiB", bytes >> 20);
  else if (bytes >= (1u << 20))
    std::snprintf(buffer, sizeof buffer, "%.1f MiB", static_cast<double>(bytes) / (1u << 20));
  else
    std::snprintf(buffer, sizeof buffer, "%zu KiB", (bytes + 1023) / 1024);
  return buffer;
}

}  // namespace stereoshift
