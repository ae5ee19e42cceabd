// The HLSL splice's scanner: see scanner.h.
#include "transpiler/backend/hlsl_splice/scanner.h"

#include "passes/source_text.h"

#include <algorithm>
#include <cctype>

namespace stereoshift::hlsl_splice {

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

bool isValidIdentifier(const std::string& s) {
  if (s.empty() || !isIdentStart(s[0])) return false;
  return std::all_of(s.begin(), s.end(), isIdentifierChar);
}

std::optional<SpliceError> Scanner::run() {
  size_t i = begin_;
  bool lineStart = (i == 0 || s_[i - 1] == '\n');
  if (i == 0 && s_.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // UTF-8 byte order mark
  while (i < end_) {
    char c = s_[i];
    if (c == '\n') {
      lineStart = true;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    if (c == '\\' && lineSplice(i) != 0) {
      i += lineSplice(i);
      continue;
    }
    if (c == '/' && at(i + 1) == '/') {
      i = lineCommentEnd(i);
      continue;
    }
    if (c == '/' && at(i + 1) == '*') {
      size_t close = s_.find("*/", i + 2);
      if (close == npos || close + 2 > end_) return SpliceError{i, "unterminated /* comment"};
      blockComments.push_back({i, close + 2});
      i = close + 2;
      continue;
    }
    if (c == '#' && lineStart && directives_) {
      auto err = directive(i);
      if (err) return err;
      i = directivesList.back().end;
      continue;
    }
    lineStart = false;
    size_t start = i;
    if (isIdentStart(c)) {
      while (i < end_ && isIdentifierChar(s_[i])) ++i;
      tokens.push_back({TokKind::Ident, start, i});
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && std::isdigit(static_cast<unsigned char>(at(i + 1))))) {
      ++i;
      while (i < end_) {
        char d = s_[i];
        if ((d == '+' || d == '-') && (s_[i - 1] == 'e' || s_[i - 1] == 'E')) {
          ++i;
        } else if (isIdentifierChar(d) || d == '.') {
          ++i;
        } else {
          break;
        }
      }
      tokens.push_back({TokKind::Number, start, i});
    } else if (c == '"' || c == '\'') {
      ++i;
      while (true) {
        if (i >= end_ || s_[i] == '\n') return SpliceError{start, "unterminated string literal"};
        if (s_[i] == '\\') {
          i += 2;
          continue;
        }
        if (s_[i] == c) break;
        ++i;
      }
      ++i;
      tokens.push_back({TokKind::String, start, i});
    } else {
      ++i;
      tokens.push_back({TokKind::Punct, start, i});
    }
  }
  return std::nullopt;
}

std::vector<Token> tokens;
std::vector<Directive> directivesList;
std::vector<Span> blockComments;

// Length of a backslash-newline line splice at i, 0 if none.
size_t Scanner::lineSplice(size_t i) const {
  if (at(i) != '\\') return 0;
  if (at(i + 1) == '\n') return 2;
  if (at(i + 1) == '\r' && at(i + 2) == '\n') return 3;
  return 0;
}


// From "//" at i to the newline that ends the comment (line splices continue it).
size_t Scanner::lineCommentEnd(size_t i) const {
  while (i < end_ && s_[i] != '\n') {
    size_t splice = lineSplice(i);
    i += splice ? splice : 1;
  }
  return i;
}

std::optional<SpliceError> Scanner::directive(size_t hash) {
  Directive d;
  d.begin = hash;
  size_t i = hash + 1;
  auto skipBlanks = [&] {
    while (i < end_ && (s_[i] == ' ' || s_[i] == '\t')) ++i;
  };
  skipBlanks();
  size_t nameBegin = i;
  while (i < end_ && isIdentifierChar(s_[i])) ++i;
  d.name = s_.substr(nameBegin, i - nameBegin);
  if (d.name == "define") {
    skipBlanks();
    size_t mb = i;
    while (i < end_ && isIdentifierChar(s_[i])) ++i;
    d.macroName = s_.substr(mb, i - mb);
    if (at(i) == '(') {
      while (i < end_ && s_[i] != ')' && s_[i] != '\n') ++i;
      if (at(i) == ')') ++i;
    }
    d.bodyBegin = i;
  }
  // Find the end of the logical line; comments and strings inside the directive are skipped.
  while (i < end_ && s_[i] != '\n') {
    if (size_t splice = lineSplice(i)) {
      i += splice;
    } else if (s_[i] == '/' && at(i + 1) == '/') {
      i = lineCommentEnd(i);
    } else if (s_[i] == '/' && at(i + 1) == '*') {
      size_t close = s_.find("*/", i + 2);
      if (close == npos || close + 2 > end_) return SpliceError{i, "unterminated /* comment"};
      blockComments.push_back({i, close + 2});
      i = close + 2;
    } else if (s_[i] == '"') {
      size_t start = i++;
      while (i < end_ && s_[i] != '"' && s_[i] != '\n') i += (s_[i] == '\\') ? 2 : 1;
      if (at(i) != '"') return SpliceError{start, "unterminated string literal"};
      ++i;
    } else {
      ++i;
    }
  }
  d.end = std::min(i, end_);
  if (d.bodyBegin > d.end) d.bodyBegin = d.end;
  directivesList.push_back(std::move(d));
  return std::nullopt;
}

std::optional<SpliceError> matchBrackets(const std::string& s, const std::vector<Token>& toks,
                                         std::vector<size_t>& match) {
  match.assign(toks.size(), npos);
  std::vector<size_t> stack;
  auto ch = [&](size_t k) { return toks[k].kind == TokKind::Punct ? s[toks[k].begin] : '\0'; };
  for (size_t k = 0; k < toks.size(); ++k) {
    char c = ch(k);
    if (c == '(' || c == '[' || c == '{') {
      stack.push_back(k);
    } else if (c == ')' || c == ']' || c == '}') {
      char want = c == ')' ? '(' : c == ']' ? '[' : '{';
      if (stack.empty()) return SpliceError{toks[k].begin, std::string("unbalanced '") + c + "': nothing to close"};
      size_t open = stack.back();
      if (ch(open) != want) {
        return SpliceError{toks[open].begin, std::string("unbalanced '") + ch(open) + "': closed by '" + c + "'"};
      }
      stack.pop_back();
      match[open] = k;
      match[k] = open;
    }
  }
  if (!stack.empty()) {
    return SpliceError{toks[stack.back()].begin, std::string("unbalanced '") + ch(stack.back()) + "': never closed"};
  }
  return std::nullopt;
}

std::optional<SpliceError> TokenView::scan() {
  Scanner scanner(s, 0, s.size(), true);
  if (auto err = scanner.run()) return err;
  tokens = std::move(scanner.tokens);
  directives = std::move(scanner.directivesList);
  blockComments = std::move(scanner.blockComments);
  return matchBrackets(s, tokens, match);
}

void TokenView::locate(size_t offset, int& line, int& col) const {
  line = 1;
  size_t ls = 0;
  for (size_t i = 0; i < offset && i < s.size(); ++i) {
    if (s[i] == '\n') {
      ++line;
      ls = i + 1;
    }
  }
  col = static_cast<int>(offset - ls) + 1;
}

std::string TokenView::where(size_t offset) const {
  int l, c;
  locate(offset, l, c);
  return std::to_string(l) + ":" + std::to_string(c);
}

size_t TokenView::skipToSemicolon(size_t k) const {
  while (k < tokens.size()) {
    if (isPunct(k, ';') || isPunct(k, '}')) return k;
    if (isPunct(k, '(') || isPunct(k, '[') || isPunct(k, '{')) {
      k = match[k] + 1;
      continue;
    }
    ++k;
  }
  return k;
}

}  // namespace stereoshift::hlsl_splice
