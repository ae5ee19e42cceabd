// The HLSL splice's view of a file's tokens: see token_view.h.
#include "transpiler/backend/hlsl_splice/token_view.h"

#include "transpiler/source/lexer.h"

#include <cctype>

namespace stereoshift::hlsl_splice {

bool isPositionSemantic(std::string_view semantic) {
  std::string l = lower(semantic);
  return l == "sv_position" || l == "sv_position0";
}

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

namespace {

TokKind kindOf(source::TokenKind kind) {
  switch (kind) {
    case source::TokenKind::Identifier: return TokKind::Ident;
    case source::TokenKind::Number: return TokKind::Number;
    case source::TokenKind::String: return TokKind::String;
    default: return TokKind::Punct;
  }
}

// Reads the tokens of one directive's line into it: the name, and for a #define the macro's name,
// its parameter list (a `(` right after the name) and the body.
class DirectiveReader {
 public:
  DirectiveReader(const std::string& s, Directive& d) : s_(s), d_(d) {}

  void add(const source::Token& t) {
    switch (part_) {
      case Part::Name:
        part_ = Part::Rest;
        if (t.kind != source::TokenKind::Identifier) return;
        d_.name = source::spelledString(s_, t);
        if (d_.name == "define") {
          part_ = Part::MacroName;
          d_.bodyBegin = t.end;
        }
        return;
      case Part::MacroName:
        part_ = Part::Body;
        if (t.kind == source::TokenKind::Identifier) {
          d_.macroName = source::spelledString(s_, t);
          d_.bodyBegin = t.end;
          part_ = Part::AfterMacroName;
          return;
        }
        break;
      case Part::AfterMacroName:
        part_ = Part::Body;
        if (t.kind == source::TokenKind::Punctuation && s_[t.begin] == '(' && t.begin == d_.bodyBegin) {
          part_ = Part::Parameters;
          d_.bodyBegin = d_.end;  // until the list closes
          return;
        }
        break;
      case Part::Parameters:
        if (t.kind == source::TokenKind::Punctuation && s_[t.begin] == ')') {
          d_.bodyBegin = t.end;
          part_ = Part::Body;
        }
        return;
      case Part::Body:
        break;
      case Part::Rest:
        return;
    }
    if (t.kind == source::TokenKind::String && t.unterminated) d_.bodyReadable = false;
    d_.body.push_back({kindOf(t.kind), t.begin, t.end});
  }

 private:
  enum class Part { Name, MacroName, AfterMacroName, Parameters, Body, Rest };
  const std::string& s_;
  Directive& d_;
  Part part_ = Part::Name;
};

}  // namespace

std::optional<SpliceError> TokenView::scan() {
  tokens.clear();
  directives.clear();
  blockComments.clear();
  source::Lexer lexer(s);
  source::Token t;
  std::optional<DirectiveReader> directive;
  while (lexer.next(t)) {
    if (t.kind == source::TokenKind::Comment) {
      if (!source::isBlockComment(s, t)) continue;
      if (t.unterminated) return SpliceError{t.begin, "unterminated /* comment"};
      blockComments.push_back({t.begin, t.end});
      continue;
    }
    if (t.kind == source::TokenKind::String && t.unterminated && (!t.inDirective() || s[t.begin] == '"'))
      return SpliceError{t.begin, "unterminated string literal"};
    if (t.kind == source::TokenKind::Directive) {
      directives.push_back({});
      directives.back().begin = t.begin;
      directives.back().end = t.end;
      directive.emplace(s, directives.back());
      continue;
    }
    if (t.inDirective()) {
      directive->add(t);
      continue;
    }
    tokens.push_back({kindOf(t.kind), t.begin, t.end});
  }
  return matchBrackets(s, tokens, match);
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
