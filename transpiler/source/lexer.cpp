// This turns GLSL and HLSL source text into tokens with offsets, lines, directives and #if depth:
// see lexer.h for what a token is. One forward pass; a directive's line is looked ahead once to
// find where it ends (block comments and strings may carry it past a line break).
#include "transpiler/source/lexer.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace stereoshift::source {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

struct NamedDirective {
  const char* name;
  DirectiveKind kind;
};
constexpr NamedDirective kDirectives[] = {
    {"version", DirectiveKind::Version}, {"extension", DirectiveKind::Extension},
    {"include", DirectiveKind::Include}, {"pragma", DirectiveKind::Pragma},
    {"define", DirectiveKind::Define},   {"undef", DirectiveKind::Undef},
    {"if", DirectiveKind::If},           {"ifdef", DirectiveKind::Ifdef},
    {"ifndef", DirectiveKind::Ifndef},   {"elif", DirectiveKind::Elif},
    {"else", DirectiveKind::Else},       {"endif", DirectiveKind::Endif},
    {"line", DirectiveKind::Line},       {"error", DirectiveKind::Error},
};

}  // namespace

const char* directiveKindName(DirectiveKind kind) {
  for (const auto& d : kDirectives)
    if (d.kind == kind) return d.name;
  return "";
}

Lexer::Lexer(std::string_view text) : text_(text) {
  if (text_.size() >= 3 && text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;  // UTF-8 byte order mark
}

// Length of a backslash-newline at `i` ("\\\n" or "\\\r\n"), 0 when there is none.
size_t Lexer::spliceLength(size_t i) const {
  if (at(i) != '\\') return 0;
  if (at(i + 1) == '\n') return 2;
  if (at(i + 1) == '\r' && at(i + 2) == '\n') return 3;
  return 0;
}

bool Lexer::hasSplice(size_t begin, size_t end) const {
  const char* base = text_.data();
  for (size_t i = begin; i < end;) {
    const void* hit = std::memchr(base + i, '\\', end - i);
    if (!hit) return false;
    i = static_cast<size_t>(static_cast<const char*>(hit) - base);
    if (spliceLength(i)) return true;
    ++i;
  }
  return false;
}

size_t Lexer::skipSplices(size_t i) const {
  while (size_t n = spliceLength(i)) i += n;
  return i;
}

void Lexer::countLinesTo(size_t offset) {
  const char* base = text_.data();
  size_t i = counted_;
  while (i < offset) {
    const void* hit = std::memchr(base + i, '\n', offset - i);
    if (!hit) break;
    i = static_cast<size_t>(static_cast<const char*>(hit) - base) + 1;
    ++line_;
    lineStart_ = i;
  }
  counted_ = offset;
}

// From `//` at `i` to the end of its logical line (without the line break and a '\r' before it).
size_t Lexer::lineCommentEnd(size_t i) const {
  const char* base = text_.data();
  const size_t n = text_.size();
  for (size_t j = i; j < n;) {
    const void* hit = std::memchr(base + j, '\n', n - j);
    if (!hit) return n;
    size_t newline = static_cast<size_t>(static_cast<const char*>(hit) - base);
    size_t before = newline > i && base[newline - 1] == '\r' ? newline - 1 : newline;
    if (before > i && base[before - 1] == '\\') {  // a splice: the comment goes on
      j = newline + 1;
      continue;
    }
    return before;
  }
  return n;
}

// From `/*` at `i` past its `*/` (which a splice may split), or to the end of the text.
size_t Lexer::blockCommentEnd(size_t i, bool* closed) const {
  const char* base = text_.data();
  const size_t n = text_.size();
  size_t j = skipSplices(i + 1) + 1;  // past the opening `*`
  while (j < n) {
    const void* hit = std::memchr(base + j, '*', n - j);
    if (!hit) break;
    size_t star = static_cast<size_t>(static_cast<const char*>(hit) - base);
    size_t after = skipSplices(star + 1);
    if (at(after) == '/') {
      *closed = true;
      return after + 1;
    }
    j = star + 1;
  }
  *closed = false;
  return n;
}

// From the quote at `i` past the matching `close`, or to the end of the line when it is left open.
size_t Lexer::quotedEnd(size_t i, char close, bool* closed, bool* spliced) const {
  const size_t n = text_.size();
  size_t j = i + 1;
  while (j < n) {
    char c = text_[j];
    if (c == '\\') {
      if (size_t s = spliceLength(j)) {
        *spliced = true;
        j += s;
      } else {
        j = std::min(n, j + 2);  // an escape: the next character is part of the literal
      }
      continue;
    }
    if (c == '\n') {
      *closed = false;
      return j > i + 1 && text_[j - 1] == '\r' ? j - 1 : j;
    }
    ++j;
    if (c == close) {
      *closed = true;
      return j;
    }
  }
  *closed = false;
  return n;
}

size_t Lexer::identifierEnd(size_t i, bool* spliced) const {
  size_t j = i + 1;
  for (;;) {
    size_t k = skipSplices(j);
    if (k >= text_.size() || !isIdentifierChar(text_[k])) return j;
    if (k != j) *spliced = true;
    j = k + 1;
  }
}

size_t Lexer::numberEnd(size_t i, bool* spliced) const {
  size_t j = skipSplices(i + 1);
  if (text_[i] == '.') {  // `.5`: the digit after the dot is part of it
    if (j != i + 1) *spliced = true;
    ++j;
  } else {
    j = i + 1;
  }
  char previous = text_[j - 1];
  for (;;) {
    size_t k = skipSplices(j);
    char c = at(k);
    bool part = k < text_.size() &&
                (isIdentifierChar(c) || c == '.' || ((c == '+' || c == '-') && (previous == 'e' || previous == 'E')));
    if (!part) return j;
    if (k != j) *spliced = true;
    previous = c;
    j = k + 1;
  }
}

// Past blanks, splices and block comments from `i` (not past a line break outside a comment).
size_t Lexer::skipBlanks(size_t i) const {
  for (;;) {
    while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\f' || text_[i] == '\v')) ++i;
    if (size_t s = spliceLength(i)) {
      i += s;
      continue;
    }
    if (at(i) == '/' && at(skipSplices(i + 1)) == '*') {
      bool closed = false;
      i = blockCommentEnd(i, &closed);
      continue;
    }
    return i;
  }
}

DirectiveKind Lexer::directiveAt(size_t hash) const {
  size_t i = skipBlanks(hash + 1);
  if (!isIdentifierStart(at(i))) return DirectiveKind::Other;
  char name[16];
  size_t length = 0;
  bool spliced = false;
  size_t end = identifierEnd(i, &spliced);
  for (size_t k = i; k < end; ++k) {
    if (size_t s = spliceLength(k)) {
      k += s - 1;
      continue;
    }
    if (length == sizeof name) return DirectiveKind::Other;
    name[length++] = text_[k];
  }
  std::string_view written(name, length);
  for (const auto& d : kDirectives)
    if (written == d.name) return d.kind;
  return DirectiveKind::Other;
}

// Where the logical line of the directive whose `#` is at `hash` ends: at the first line break that
// no splice, block comment or string carries on (before a '\r' ahead of it), or at the end.
size_t Lexer::logicalLineEnd(size_t hash, DirectiveKind kind) const {
  const size_t n = text_.size();
  // `#include <a/b.h>`: the header name is one string, whatever it holds.
  size_t headerName = std::string::npos;
  if (kind == DirectiveKind::Include) {
    size_t name = skipBlanks(hash + 1);
    bool spliced = false;
    size_t operand = skipBlanks(identifierEnd(name, &spliced));
    if (at(operand) == '<') headerName = operand;
  }
  size_t i = hash + 1;
  while (i < n) {
    char c = text_[i];
    if (c == '\n') break;
    bool closed = false, spliced = false;
    if (c == '\\') {
      size_t s = spliceLength(i);
      i += s ? s : 1;
    } else if (c == '/' && at(skipSplices(i + 1)) == '/') {
      return lineCommentEnd(i);
    } else if (c == '/' && at(skipSplices(i + 1)) == '*') {
      i = blockCommentEnd(i, &closed);
    } else if (c == '"' || c == '\'') {
      i = quotedEnd(i, c, &closed, &spliced);
    } else if (i == headerName) {
      while (i < n && text_[i] != '\n' && text_[i] != '>') ++i;
      if (at(i) == '>') ++i;
    } else {
      ++i;
    }
  }
  if (i > hash + 1 && i < n && text_[i] == '\n' && text_[i - 1] == '\r') --i;
  return std::min(i, n);
}

void Lexer::beginDirective(Token& token, size_t hash) {
  DirectiveKind kind = directiveAt(hash);
  token.kind = TokenKind::Directive;
  token.directive = kind;
  token.end = logicalLineEnd(hash, kind);
  switch (kind) {
    case DirectiveKind::If:
    case DirectiveKind::Ifdef:
    case DirectiveKind::Ifndef:
      directiveDepth_ = depth_++;
      break;
    case DirectiveKind::Elif:
    case DirectiveKind::Else:
      directiveDepth_ = depth_ > 0 ? depth_ - 1 : 0;
      break;
    case DirectiveKind::Endif:
      if (depth_ > 0) --depth_;
      else ++unbalancedEndifs_;
      directiveDepth_ = depth_;
      break;
    default:
      directiveDepth_ = depth_;
      break;
  }
  token.ifDepth = directiveDepth_;
  directive_ = kind;
  directiveEnd_ = token.end;
  sawDirectiveName_ = false;
  expectHeaderName_ = false;
  pos_ = hash + 1;
}

bool Lexer::next(Token& token) {
  if (peeked_) {
    peeked_ = false;
    token = peek_;
    return true;
  }
  return lex(token);
}

std::vector<Token> Lexer::directiveWords() {
  std::vector<Token> words;
  Token t;
  while (next(t)) {
    if (!t.inDirective()) {
      peek_ = t;
      peeked_ = true;
      break;
    }
    if (t.kind != TokenKind::Comment) words.push_back(t);
  }
  return words;
}

bool Lexer::lex(Token& token) {
  const size_t n = text_.size();
  const bool inDirective = directive_ != DirectiveKind::None;
  const size_t limit = inDirective ? directiveEnd_ : n;
  size_t i = pos_;
  for (;;) {
    while (i < limit && isBlank(text_[i])) ++i;
    if (i < limit && text_[i] == '\n') {  // outside directives only: a directive's line ends before it
      atLineStart_ = true;
      ++i;
      continue;
    }
    if (size_t s = spliceLength(i); s && i < limit) {
      i += s;
      continue;
    }
    break;
  }
  if (inDirective && i >= directiveEnd_) {  // the directive's line is read: back to the text around it
    directive_ = DirectiveKind::None;
    expectHeaderName_ = false;  // `#include` with no header on its line: a later `<` is an operator
    pos_ = std::max(i, directiveEnd_);
    return lex(token);
  }
  if (i >= n) {
    pos_ = n;
    return false;
  }
  countLinesTo(i);
  token = Token{};
  token.begin = i;
  token.line = line_;
  token.column = static_cast<uint32_t>(i - lineStart_ + 1);
  token.directive = directive_;
  token.ifDepth = inDirective ? directiveDepth_ : depth_;
  const char c = text_[i];
  bool closed = true, spliced = false;
  if (c == '/' && at(skipSplices(i + 1)) == '/') {
    token.kind = TokenKind::Comment;
    token.end = lineCommentEnd(i);
  } else if (c == '/' && at(skipSplices(i + 1)) == '*') {
    token.kind = TokenKind::Comment;
    token.end = blockCommentEnd(i, &closed);
  } else if (c == '#' && !inDirective && atLineStart_) {
    beginDirective(token, i);
    atLineStart_ = false;
    return true;
  } else if (c == '"' || c == '\'') {
    token.kind = TokenKind::String;
    token.end = quotedEnd(i, c, &closed, &spliced);
  } else if (c == '<' && expectHeaderName_ && inDirective) {
    size_t j = i + 1;
    while (j < directiveEnd_ && text_[j] != '>') ++j;
    closed = j < directiveEnd_;
    token.kind = TokenKind::String;
    token.end = closed ? j + 1 : directiveEnd_;
  } else if (isIdentifierStart(c)) {
    token.kind = TokenKind::Identifier;
    token.end = identifierEnd(i, &spliced);
  } else if (isDecimalDigit(c) || (c == '.' && isDecimalDigit(at(skipSplices(i + 1))))) {
    token.kind = TokenKind::Number;
    token.end = numberEnd(i, &spliced);
  } else {
    token.kind = TokenKind::Punctuation;
    token.end = i + 1;
  }
  if (inDirective) token.end = std::min(token.end, directiveEnd_);
  token.unterminated = !closed;
  token.spliced = spliced || (token.kind == TokenKind::Comment && hasSplice(token.begin, token.end));
  if (token.kind != TokenKind::Comment) {
    atLineStart_ = false;
    if (inDirective) {
      // The directive's name comes first; after `#include`'s, a `<...>` is a header name.
      expectHeaderName_ = !sawDirectiveName_ && directive_ == DirectiveKind::Include;
      sawDirectiveName_ = true;
    }
  }
  pos_ = token.end;
  return true;
}

std::vector<Token> lex(std::string_view text) {
  std::vector<Token> tokens;
  tokens.reserve(text.size() / 6 + 16);
  Lexer lexer(text);
  Token t;
  while (lexer.next(t)) tokens.push_back(t);
  return tokens;
}

bool isBlockComment(std::string_view text, const Token& t) {
  if (t.kind != TokenKind::Comment) return false;
  std::string scratch;
  std::string_view spelled = spelling(text, t, scratch);
  return spelled.size() >= 2 && spelled[1] == '*';
}

std::string_view spelling(std::string_view text, const Token& t, std::string& scratch) {
  std::string_view raw = tokenText(text, t);
  if (!t.spliced) return raw;
  scratch.clear();
  for (size_t k = 0; k < raw.size(); ++k) {
    if (raw[k] == '\\' && k + 1 < raw.size() && raw[k + 1] == '\n') {
      ++k;
    } else if (raw[k] == '\\' && k + 2 < raw.size() && raw[k + 1] == '\r' && raw[k + 2] == '\n') {
      k += 2;
    } else {
      scratch += raw[k];
    }
  }
  return scratch;
}

std::string spelledString(std::string_view text, const Token& t) {
  std::string scratch;
  return std::string(spelling(text, t, scratch));
}

std::string splicesOf(std::string_view text, const Token& t) {
  std::string out;
  if (!t.spliced) return out;
  std::string_view raw = tokenText(text, t);
  for (size_t k = 0; k + 1 < raw.size(); ++k) {
    if (raw[k] != '\\') continue;
    if (raw[k + 1] == '\n') out += "\\\n";
    else if (raw[k + 1] == '\r' && k + 2 < raw.size() && raw[k + 2] == '\n') out += "\\\r\n";
  }
  return out;
}

bool nulsOnlyInCommentsOrAtEnd(std::string_view text) {
  size_t end = text.size();
  while (end > 0 && (text[end - 1] == '\0' || std::isspace(static_cast<unsigned char>(text[end - 1])))) --end;
  size_t nul = text.find('\0');
  if (nul >= end) return true;
  const std::vector<Token> tokens = lex(text.substr(0, end));
  size_t k = 0;
  for (; nul < end; nul = text.find('\0', nul + 1)) {
    while (k < tokens.size() && tokens[k].end <= nul) ++k;
    if (k == tokens.size() || tokens[k].begin > nul || tokens[k].kind != TokenKind::Comment) return false;
  }
  return true;
}

std::string blankNuls(std::string text) {
  std::replace(text.begin(), text.end(), '\0', ' ');
  return text;
}

std::pair<int, int> lineAndColumn(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
  size_t lineStart = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  lineStart = (lineStart == std::string_view::npos || offset == 0) ? 0 : lineStart + 1;
  return {line, static_cast<int>(offset - lineStart) + 1};
}

size_t LexedText::nextNonComment(size_t k) const {
  size_t j = k + 1;
  while (j < tokens_.size() && tokens_[j].kind == TokenKind::Comment) ++j;
  return j;
}

std::string_view LexedText::directiveName(size_t k) const {
  size_t j = nextNonComment(k);
  return j < tokens_.size() && tokens_[j].inDirective() && tokens_[j].kind == TokenKind::Identifier ? text(j)
                                                                                                     : std::string_view();
}

size_t LexedText::firstOperand(size_t k) const {
  size_t j = nextNonComment(k);
  if (j >= tokens_.size() || !tokens_[j].inDirective()) return tokens_.size();
  if (tokens_[j].kind == TokenKind::Identifier) j = nextNonComment(j);  // past the name
  return j < tokens_.size() && tokens_[j].inDirective() ? j : tokens_.size();
}

size_t LexedText::directiveLineEnd(size_t k) const {
  size_t j = k + 1;
  while (j < tokens_.size() && tokens_[j].inDirective()) ++j;
  return j;
}

}  // namespace stereoshift::source
