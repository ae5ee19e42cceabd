// HLSL source splice for geometry and domain shaders: see hlsl_splice.h.
#include "transpiler/backend/hlsl_splice.h"
#include "passes/source_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stereoshift {
namespace {

constexpr const char* kPrefix = "stereoshift";
constexpr size_t npos = std::string::npos;

// ------------------------------------------------------------------------------------------------
// Scanner
// ------------------------------------------------------------------------------------------------

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
};

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

class Scanner {
 public:
  // `directives`: recognise preprocessor lines (false when scanning the body of a #define, where
  // '#' is the stringizing operator).
  Scanner(const std::string& src, size_t begin, size_t end, bool directives)
      : s_(src), begin_(begin), end_(end), directives_(directives) {}

  std::optional<SpliceError> run() {
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

 private:
  char at(size_t i) const { return i < end_ ? s_[i] : '\0'; }

  // Length of a backslash-newline line splice at i, 0 if none.
  size_t lineSplice(size_t i) const {
    if (at(i) != '\\') return 0;
    if (at(i + 1) == '\n') return 2;
    if (at(i + 1) == '\r' && at(i + 2) == '\n') return 3;
    return 0;
  }

  // From "//" at i to the newline that ends the comment (line splices continue it).
  size_t lineCommentEnd(size_t i) const {
    while (i < end_ && s_[i] != '\n') {
      size_t splice = lineSplice(i);
      i += splice ? splice : 1;
    }
    return i;
  }

  std::optional<SpliceError> directive(size_t hash) {
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

  const std::string& s_;
  size_t begin_, end_;
  bool directives_;
};

// Matching bracket for every (, [, { and their closers; npos elsewhere.
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

// ------------------------------------------------------------------------------------------------
// Declarations
// ------------------------------------------------------------------------------------------------

const std::set<std::string>& modifierWords() {
  static const std::set<std::string> words = {
      "in", "out", "inout", "const", "uniform", "static", "precise", "inline", "extern", "volatile",
      "shared", "groupshared", "linear", "centroid", "nointerpolation", "noperspective", "sample",
      "point", "line", "triangle", "lineadj", "triangleadj", "row_major", "column_major", "snorm",
      "unorm", "globallycoherent", "vertices", "indices", "primitives", "payload", "struct", "class"};
  return words;
}

bool isFloat4Like(const std::string& type) {
  static const std::set<std::string> types = {"float4", "half4", "min16float4", "min10float4",
                                              "double4", "vector"};
  return types.count(type) != 0;
}

struct Param {
  size_t begin = 0, end = 0;  // token range
  std::string name;
  size_t nameTok = npos;
  std::string typeName;  // last non-modifier identifier of the type (outside template arguments)
  bool isOut = false;    // `out` or `inout`
  std::string semantic;
  std::string streamElement;  // TriangleStream/LineStream/PointStream<T>: T
};

struct Attr {
  size_t open, close;  // token indices of '[' and ']'
};

struct Function {
  std::vector<Attr> attrs;
  size_t declBegin = 0;  // first token (attributes included)
  size_t typeBegin = 0;  // first token after the attributes
  size_t nameTok = 0;
  size_t paramOpen = 0, paramClose = 0;
  size_t semColon = npos, semTok = npos;  // `: SEMANTIC` after the parameter list
  size_t bodyOpen = 0, bodyClose = 0;
  std::vector<Param> params;
};

struct Member {
  std::string name;
  std::string typeName;
  std::string semantic;
};

struct StructDef {
  std::string name;
  size_t nameTok = 0;
  size_t endTok = 0;  // last token of the definition (normally ';')
  std::vector<Member> members;
};

struct Shift {
  std::string type;      // HLSL type of the helper parameter/return
  std::string function;  // helper name
  std::string access;    // member path inside the value, e.g. ".Position" ("" for a float4)
};

class Splicer {
 public:
  Splicer(const std::string& src, const HlslSpliceOptions& opt) : s_(src), opt_(opt) {}

  HlslSpliceResult run() {
    HlslSpliceResult result;
    std::optional<SpliceError> err = runImpl();
    if (err) {
      result.error = err->message;
      if (err->offset != npos) locate(err->offset, result.line, result.column);
      return result;
    }
    result.ok = true;
    result.text = applyEdits();
    result.sites = sites_;
    return result;
  }

 private:
  // ---------------------------------------------------------------- token helpers
  std::string_view text(size_t k) const {
    return std::string_view(s_).substr(toks_[k].begin, toks_[k].end - toks_[k].begin);
  }
  bool isPunct(size_t k, char c) const {
    return k < toks_.size() && toks_[k].kind == TokKind::Punct && s_[toks_[k].begin] == c;
  }
  bool isIdent(size_t k) const { return k < toks_.size() && toks_[k].kind == TokKind::Ident; }
  bool isWord(size_t k, std::string_view w) const { return isIdent(k) && text(k) == w; }
  std::string src(size_t b, size_t e) const { return s_.substr(b, e - b); }
  std::string tokSpan(size_t first, size_t last) const {  // inclusive token range, verbatim
    return src(toks_[first].begin, toks_[last].end);
  }
  SpliceError errAt(size_t tok, std::string msg) const { return {toks_[tok].begin, std::move(msg)}; }

  void locate(size_t offset, int& line, int& col) const {
    line = 1;
    size_t ls = 0;
    for (size_t i = 0; i < offset && i < s_.size(); ++i) {
      if (s_[i] == '\n') {
        ++line;
        ls = i + 1;
      }
    }
    col = static_cast<int>(offset - ls) + 1;
  }
  std::string where(size_t offset) const {
    int l, c;
    locate(offset, l, c);
    return std::to_string(l) + ":" + std::to_string(c);
  }

  // Index of the ';' ending the declaration starting at k (brackets skipped), or the '}' that
  // closes the enclosing scope, or the token count.
  size_t skipToSemicolon(size_t k) const {
    while (k < toks_.size()) {
      if (isPunct(k, ';') || isPunct(k, '}')) return k;
      if (isPunct(k, '(') || isPunct(k, '[') || isPunct(k, '{')) {
        k = match_[k] + 1;
        continue;
      }
      ++k;
    }
    return k;
  }

  // ---------------------------------------------------------------- top level
  std::optional<SpliceError> parseTopLevel() {
    size_t n = toks_.size();
    size_t i = 0;
    std::optional<size_t> declBegin;
    std::vector<Attr> attrs;
    size_t afterAttrs = npos;
    std::set<size_t> namespaceOpeners;
    auto reset = [&] {
      declBegin.reset();
      attrs.clear();
      afterAttrs = npos;
    };
    while (i < n) {
      if (isPunct(i, '[') && (!declBegin || afterAttrs == i)) {
        attrs.push_back({i, match_[i]});
        if (!declBegin) declBegin = i;
        i = match_[i] + 1;
        afterAttrs = i;
        continue;
      }
      if (isPunct(i, ';')) {
        reset();
        ++i;
        continue;
      }
      if (isPunct(i, '}')) {
        if (!namespaceOpeners.count(match_[i])) return errAt(i, "unexpected '}' at file scope");
        reset();
        ++i;
        continue;
      }
      if (!declBegin) declBegin = i;
      if ((isWord(i, "struct") || isWord(i, "class") || isWord(i, "interface")) && isIdent(i + 1) &&
          (isPunct(i + 2, '{') || isPunct(i + 2, ':'))) {
        size_t open = i + 2;
        while (open < n && !isPunct(open, '{') && !isPunct(open, ';')) ++open;
        if (open < n && isPunct(open, '{')) {
          StructDef sd;
          sd.name = std::string(text(i + 1));
          sd.nameTok = i + 1;
          parseMembers(open, match_[open], sd.members);
          size_t semi = skipToSemicolon(match_[open] + 1);
          collectNames(match_[open] + 1, semi);
          sd.endTok = semi < n && isPunct(semi, ';') ? semi : match_[open];
          topNames_[sd.name] = sd.nameTok;
          structs_.push_back(std::move(sd));
          reset();
          i = semi < n && isPunct(semi, ';') ? semi + 1 : semi;
          continue;
        }
      }
      if (isWord(i, "cbuffer") || isWord(i, "tbuffer")) {
        if (isIdent(i + 1)) topNames_[std::string(text(i + 1))] = i + 1;
        size_t open = i + 1;
        while (open < n && !isPunct(open, '{') && !isPunct(open, ';')) ++open;
        if (open < n && isPunct(open, '{')) {
          // Members are declarations at file scope.
          size_t k = open + 1;
          while (k < match_[open]) {
            size_t semi = skipToSemicolon(k);
            collectNames(k, std::min(semi, match_[open]));
            k = semi + 1;
          }
          i = match_[open] + 1;
          if (isPunct(i, ';')) ++i;
        } else {
          i = open + 1;
        }
        reset();
        continue;
      }
      if (isWord(i, "namespace") && isIdent(i + 1) && isPunct(i + 2, '{')) {
        namespaceOpeners.insert(i + 2);
        i += 3;
        reset();
        continue;
      }
      if (isWord(i, "typedef")) {
        size_t semi = skipToSemicolon(i);
        if (semi > i + 1 && isIdent(semi - 1)) topNames_[std::string(text(semi - 1))] = semi - 1;
        i = semi < n && isPunct(semi, ';') ? semi + 1 : semi;
        reset();
        continue;
      }
      // A variable declaration, a prototype or a function definition.
      bool sawEquals = false;
      size_t k = i;
      bool done = false;
      while (k < n && !done) {
        if (isPunct(k, '(')) {
          if (k > i && isIdent(k - 1) && !sawEquals) {
            size_t close = match_[k];
            size_t body = npos, semColon = npos, semTok = npos;
            if (isPunct(close + 1, '{')) {
              body = close + 1;
            } else if (isPunct(close + 1, ':') && isIdent(close + 2) && isPunct(close + 3, '{')) {
              semColon = close + 1;
              semTok = close + 2;
              body = close + 3;
            }
            if (body != npos) {
              Function f;
              f.attrs = attrs;
              f.declBegin = *declBegin;
              f.typeBegin = attrs.empty() ? *declBegin : attrs.back().close + 1;
              f.nameTok = k - 1;
              f.paramOpen = k;
              f.paramClose = close;
              f.semColon = semColon;
              f.semTok = semTok;
              f.bodyOpen = body;
              f.bodyClose = match_[body];
              f.params = parseParams(k, close);
              topNames_[std::string(text(k - 1))] = k - 1;
              functions_.push_back(std::move(f));
              i = match_[body] + 1;
              done = true;
              continue;
            }
          }
          k = match_[k] + 1;
          continue;
        }
        if (isPunct(k, '[') || isPunct(k, '{')) {
          k = match_[k] + 1;
          continue;
        }
        if (isPunct(k, ';') || isPunct(k, '}')) {
          collectNames(i, k);
          i = isPunct(k, ';') ? k + 1 : k;
          done = true;
          continue;
        }
        if (isPunct(k, '=')) sawEquals = true;
        ++k;
      }
      if (!done) {
        collectNames(i, n);
        i = n;
      }
      reset();
    }
    return std::nullopt;
  }

  // Names declared by the declaration tokens [b, e): identifiers followed by ; , : = [ ( at
  // bracket depth 0, outside initializers.
  void collectNames(size_t b, size_t e) {
    bool inInit = false;
    for (size_t k = b; k < e && k < toks_.size(); ++k) {
      if (isPunct(k, '(') || isPunct(k, '[') || isPunct(k, '{')) {
        if (!inInit && k > b && isIdent(k - 1) && (isPunct(k, '[') || isPunct(k, '('))) {
          topNames_.emplace(std::string(text(k - 1)), k - 1);
        }
        k = match_[k];
        continue;
      }
      if (isPunct(k, '=')) inInit = true;
      if (isPunct(k, ',')) inInit = false;
      if (!inInit && isIdent(k) && (k + 1 == e || isPunct(k + 1, ';') || isPunct(k + 1, ',') ||
                                    isPunct(k + 1, ':') || isPunct(k + 1, '='))) {
        topNames_.emplace(std::string(text(k)), k);
      }
    }
  }

  // Struct members between the braces `open` and `close` (methods and nested types skipped).
  void parseMembers(size_t open, size_t close, std::vector<Member>& out) {
    size_t k = open + 1;
    while (k < close) {
      size_t declBegin = k;
      bool function = false, nested = false;
      while (k < close && !isPunct(k, ';')) {
        if (isPunct(k, '(')) {
          function = true;
          k = match_[k] + 1;
        } else if (isPunct(k, '[')) {
          k = match_[k] + 1;
        } else if (isPunct(k, '{')) {
          k = match_[k] + 1;
          if (function) break;  // method body: no ';' needed
          nested = true;
        } else {
          ++k;
        }
      }
      size_t declEnd = k;
      if (k < close && isPunct(k, ';')) ++k;
      if (function || nested || declEnd == declBegin) continue;
      // Declarators separated by commas; the type comes from the first one.
      std::string typeName;
      size_t d = declBegin;
      bool first = true;
      while (d < declEnd) {
        size_t de = d;
        int angle = 0;
        while (de < declEnd) {
          if (isPunct(de, '<')) ++angle;
          if (isPunct(de, '>') && angle > 0) --angle;
          if (angle == 0 && isPunct(de, ',')) break;
          if (isPunct(de, '(') || isPunct(de, '[') || isPunct(de, '{')) de = match_[de];
          ++de;
        }
        // [d, de): one declarator; name = last identifier before ':', '[' or '='.
        size_t stop = d;
        while (stop < de && !isPunct(stop, ':') && !isPunct(stop, '[') && !isPunct(stop, '=')) {
          if (isPunct(stop, '<')) {  // template arguments of the type
            int depth = 0;
            do {
              if (isPunct(stop, '<')) ++depth;
              if (isPunct(stop, '>')) --depth;
              ++stop;
            } while (stop < de && depth > 0);
            continue;
          }
          ++stop;
        }
        Member m;
        std::vector<size_t> idents;
        for (size_t t = d; t < stop; ++t) {
          if (isPunct(t, '<')) {
            int depth = 0;
            do {
              if (isPunct(t, '<')) ++depth;
              if (isPunct(t, '>')) --depth;
              ++t;
            } while (t < stop && depth > 0);
            --t;
            continue;
          }
          if (isIdent(t) && !modifierWords().count(std::string(text(t)))) idents.push_back(t);
        }
        if (!idents.empty()) {
          m.name = std::string(text(idents.back()));
          if (first && idents.size() >= 2) typeName = std::string(text(idents[idents.size() - 2]));
          m.typeName = typeName;
          for (size_t t = stop; t < de; ++t) {
            if (isPunct(t, '[')) {
              t = match_[t];
              continue;
            }
            if (isPunct(t, ':') && isIdent(t + 1) && !isWord(t + 1, "packoffset") &&
                !isWord(t + 1, "register")) {
              m.semantic = std::string(text(t + 1));
              break;
            }
          }
          out.push_back(std::move(m));
        }
        first = false;
        d = de + 1;
      }
    }
  }

  std::vector<Param> parseParams(size_t open, size_t close) const {
    std::vector<Param> params;
    size_t k = open + 1;
    while (k < close) {
      Param p;
      p.begin = k;
      int angle = 0;
      size_t e = k;
      while (e < close) {
        if (isPunct(e, '<') && e > k && isIdent(e - 1)) ++angle;
        else if (isPunct(e, '>') && angle > 0) --angle;
        else if (angle == 0 && isPunct(e, ',')) break;
        if (isPunct(e, '(') || isPunct(e, '[') || isPunct(e, '{')) e = match_[e];
        ++e;
      }
      p.end = e;
      // Declarator part: up to ':' (semantic), '=' (default) or '[' (array) at depth 0.
      size_t stop = k;
      angle = 0;
      std::vector<size_t> idents;
      for (; stop < e; ++stop) {
        if (isPunct(stop, '<') && stop > k && isIdent(stop - 1)) {
          if (angle == 0) {
            std::string_view tn = text(stop - 1);
            if (tn == "TriangleStream" || tn == "LineStream" || tn == "PointStream") {
              size_t t = stop + 1;
              std::string elem;
              while (t < e && !isPunct(t, '>')) {
                if (isIdent(t) && !isWord(t, "struct")) elem += std::string(text(t));
                ++t;
              }
              p.streamElement = elem;
            }
          }
          ++angle;
          continue;
        }
        if (isPunct(stop, '>') && angle > 0) {
          --angle;
          continue;
        }
        if (angle > 0) continue;
        if (isPunct(stop, ':') || isPunct(stop, '=') || isPunct(stop, '[')) break;
        if (isIdent(stop)) {
          std::string w(text(stop));
          if (w == "out" || w == "inout") p.isOut = true;
          if (!modifierWords().count(w)) idents.push_back(stop);
        }
      }
      if (!idents.empty()) {
        p.nameTok = idents.back();
        p.name = std::string(text(idents.back()));
        if (idents.size() >= 2) p.typeName = std::string(text(idents[idents.size() - 2]));
      }
      for (size_t t = stop; t < e; ++t) {
        if (isPunct(t, ':') && isIdent(t + 1)) {
          p.semantic = std::string(text(t + 1));
          break;
        }
      }
      if (e > k) params.push_back(std::move(p));
      k = e + 1;
    }
    return params;
  }

  const StructDef* findStruct(const std::string& name) const {
    for (const auto& sd : structs_) {
      if (sd.name == name) return &sd;
    }
    return nullptr;
  }

  // Member path (".a.b") of the SV_Position member of struct `name`, searching nested structs.
  std::optional<std::string> positionPath(const std::string& name, int depth = 0) const {
    const StructDef* sd = findStruct(name);
    if (!sd || depth > 8) return std::nullopt;
    for (const auto& m : sd->members) {
      if (lower(m.semantic) == "sv_position") return "." + m.name;
    }
    for (const auto& m : sd->members) {
      if (m.semantic.empty() && m.typeName != name) {
        if (auto sub = positionPath(m.typeName, depth + 1)) return "." + m.name + *sub;
      }
    }
    return std::nullopt;
  }

  // ---------------------------------------------------------------- edits
  struct Edit {
    size_t offset;
    size_t remove;
    std::string insert;
    size_t order;
  };
  void addEdit(size_t offset, size_t remove, std::string insert) {
    edits_.push_back({offset, remove, std::move(insert), edits_.size()});
  }
  std::string applyEdits() {
    std::stable_sort(edits_.begin(), edits_.end(), [](const Edit& a, const Edit& b) {
      return a.offset != b.offset ? a.offset < b.offset : a.order < b.order;
    });
    std::string out;
    out.reserve(s_.size() + 2048);
    size_t pos = 0;
    for (const auto& e : edits_) {
      out.append(s_, pos, e.offset - pos);
      out += e.insert;
      pos = e.offset + e.remove;
    }
    out.append(s_, pos, npos);
    return out;
  }

  std::string newline() const {
    size_t crlf = 0, lf = 0;
    for (size_t i = 0; i < s_.size(); ++i) {
      if (s_[i] == '\n') (i > 0 && s_[i - 1] == '\r') ? ++crlf : ++lf;
    }
    return crlf > lf ? "\r\n" : "\n";
  }

  size_t lineStart(size_t offset) const {
    size_t ls = s_.rfind('\n', offset == 0 ? 0 : offset - 1);
    return (offset == 0 || ls == npos) ? 0 : ls + 1;
  }
  bool inBlockComment(size_t offset) const {
    for (const auto& c : blockComments_) {
      if (c.begin < offset && offset < c.end) return true;
    }
    return false;
  }
  bool inDirective(size_t offset) const {
    for (const auto& d : directives_) {
      if (d.begin < offset && offset <= d.end) return true;
    }
    return false;
  }

  // Where to insert text that must come before the declaration starting at `offset`, not before
  // `notBefore`. Returns the offset and whether it is at a line start.
  std::pair<size_t, bool> insertionBefore(size_t offset, size_t notBefore) const {
    // Leave a preprocessor conditional that encloses the declaration when possible, so that the
    // inserted declarations exist whichever branch is compiled.
    std::vector<size_t> conds;
    for (const auto& d : directives_) {
      if (d.begin >= offset) break;
      if (d.name == "if" || d.name == "ifdef" || d.name == "ifndef") conds.push_back(d.begin);
      else if (d.name == "endif" && !conds.empty()) conds.pop_back();
    }
    for (size_t c : conds) {
      if (lineStart(c) >= notBefore) return {lineStart(c), true};
    }

    size_t ls = lineStart(offset);
    bool blank = true;
    for (size_t i = ls; i < offset; ++i) {
      if (s_[i] != ' ' && s_[i] != '\t') blank = false;
    }
    if (!blank || ls < notBefore || inBlockComment(ls) || inDirective(ls)) return {offset, false};
    // Keep a `//` comment block directly above the declaration attached to it.
    while (ls > 0) {
      size_t prev = lineStart(ls - 1);
      if (prev < notBefore || inBlockComment(prev) || inDirective(prev)) break;
      size_t t = prev;
      while (t < ls && (s_[t] == ' ' || s_[t] == '\t')) ++t;
      if (s_.compare(t, 2, "//") != 0) break;
      ls = prev;
    }
    return {ls, true};
  }

  // Insert `block` (lines ending in newlines) before the declaration at `offset`.
  void insertBlockBefore(size_t offset, size_t notBefore, const std::string& block) {
    auto [at, lineStartOk] = insertionBefore(offset, notBefore);
    std::string nl = newline();
    addEdit(at, 0, lineStartOk ? block + nl : nl + block + nl);
  }

  // Insert `block` after the token `tok` (a closing brace), starting on a new line.
  void insertBlockAfter(size_t tok, const std::string& block) {
    std::string nl = newline();
    size_t after = toks_[tok].end;
    size_t eol = s_.find('\n', after);
    size_t nextThing = npos;
    if (tok + 1 < toks_.size()) nextThing = toks_[tok + 1].begin;
    for (const auto& d : directives_) {
      if (d.begin >= after) {
        nextThing = std::min(nextThing, d.begin);
        break;
      }
    }
    for (const auto& c : blockComments_) {
      if (c.begin >= after) nextThing = std::min(nextThing, c.begin);
    }
    if (eol == npos) {
      addEdit(s_.size(), 0, nl + nl + block);
    } else if (nextThing != npos && nextThing < eol) {
      addEdit(after, 0, nl + nl + block);
    } else {
      addEdit(eol + 1, 0, nl + block);
    }
  }

  // ---------------------------------------------------------------- generated code
  std::string cbufferText() const {
    std::string nl = newline();
    return "cbuffer " + opt_.cbufferName + " : register(b" + std::to_string(opt_.cbufferRegister) + ")" + nl +
           "{" + nl + "    float " + opt_.eyeSignName + ";" + nl + "    float " + opt_.separationName + ";" + nl +
           "    float " + opt_.convergenceName + ";" + nl + "};" + nl;
  }

  std::string epsilonLiteral() const {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(opt_.epsilon));
    std::string lit = buf;
    if (lit.find_first_of(".eE") == npos) lit += ".0";
    return lit + "f";
  }

  std::string shiftFunctionText(const Shift& sh) const {
    std::string nl = newline();
    std::string v = std::string(kPrefix) + "_v";
    std::string p = v + sh.access;
    std::string shifted = p + ".x + (" + opt_.eyeSignName + " * " + opt_.separationName + ") * (" + p + ".w - " +
                          opt_.convergenceName + ")";
    std::string ind = "    ";
    std::string body;
    std::string assign;
    if (opt_.precise) {
      std::string tmp = std::string(kPrefix) + "_x";
      assign = "precise float " + tmp + " = " + shifted + ";" + nl;
      assign += "%IND%" + p + ".x = " + tmp + ";" + nl;
    } else {
      assign = p + ".x = " + shifted + ";" + nl;
    }
    auto indent = [&](const std::string& lines, const std::string& in) {
      std::string r = in + lines;
      size_t pos;
      while ((pos = r.find("%IND%")) != npos) r.replace(pos, 5, in);
      return r;
    };
    switch (opt_.cutoff) {
      case HlslSpliceOptions::Cutoff::Epsilon:
        // Same guard as the SPIR-V route: an infinite w is never shifted (0 * inf would be NaN).
        body = ind + "if (" + opt_.eyeSignName + " != 0.0f && abs(" + p + ".w - 1.0f) > " + epsilonLiteral() + " && !isinf(" + p + ".w))" + nl + ind + "{" + nl +
               indent(assign, ind + ind) + ind + "}" + nl;
        break;
      case HlslSpliceOptions::Cutoff::Exact:
        body = ind + "if (" + opt_.eyeSignName + " != 0.0f && " + p + ".w != 1.0f && !isinf(" + p + ".w))" + nl + ind + "{" + nl + indent(assign, ind + ind) + ind + "}" + nl;
        break;
      case HlslSpliceOptions::Cutoff::None:
        // Even without a cutoff, a mono draw (eyeSign 0) runs none of the shift.
        body = ind + "if (" + opt_.eyeSignName + " != 0.0f)" + nl + ind + "{" + nl + indent(assign, ind + ind) + ind + "}" + nl;
        break;
    }
    return sh.type + " " + sh.function + "(" + sh.type + " " + v + ")" + nl + "{" + nl + body + ind + "return " + v +
           ";" + nl + "}" + nl;
  }

  std::string preambleText(const std::vector<Shift>& shifts) const {
    std::string nl = newline();
    std::string t = "// ---- stereoshift: stereo parameters and clip-space shift (injected) ----" + nl;
    t += cbufferText() + nl;
    for (size_t k = 0; k < shifts.size(); ++k) t += (k ? nl : "") + shiftFunctionText(shifts[k]);
    t += "// ---- end stereoshift ----" + nl;
    return t;
  }

  // ---------------------------------------------------------------- checks
  std::optional<SpliceError> checkOptions() const {
    if (!isValidIdentifier(opt_.entryPoint)) {
      return SpliceError{npos, "invalid entry point name '" + opt_.entryPoint + "'"};
    }
    std::vector<std::string> names = {opt_.cbufferName, opt_.eyeSignName, opt_.separationName,
                                      opt_.convergenceName};
    for (const auto& n : names) {
      if (!isValidIdentifier(n)) return SpliceError{npos, "invalid stereo parameter name '" + n + "'"};
    }
    if (std::set<std::string>(names.begin(), names.end()).size() != names.size()) {
      return SpliceError{npos, "the cbuffer and stereo parameter names must be distinct"};
    }
    if (opt_.cutoff == HlslSpliceOptions::Cutoff::Epsilon && !(std::isfinite(opt_.epsilon) && opt_.epsilon > 0.0f)) {
      return SpliceError{npos, "the w cutoff epsilon must be a positive finite number"};
    }
    return std::nullopt;
  }

  // Our names must not collide with file-scope names or macros of the source (this also catches a
  // second injection into an already injected shader).
  std::optional<SpliceError> checkConflicts(const std::vector<std::string>& ours) const {
    for (const auto& name : ours) {
      auto it = topNames_.find(name);
      if (it != topNames_.end()) {
        return errAt(it->second, "'" + name + "' is already declared at file scope (already stereo-injected?)");
      }
      for (const auto& d : directives_) {
        if (d.name == "define" && d.macroName == name) {
          return SpliceError{d.begin, "'" + name + "' is already defined as a macro"};
        }
      }
    }
    // register(b<N>) or register(b<N>, space0) already in use.
    for (size_t k = 0; k + 2 < toks_.size(); ++k) {
      if (!isWord(k, "register") || !isPunct(k + 1, '(') || !isIdent(k + 2)) continue;
      std::string reg = lower(text(k + 2));
      if (reg != "b" + std::to_string(opt_.cbufferRegister)) continue;
      bool space0 = true;
      if (isPunct(k + 3, ',') && isIdent(k + 4)) space0 = lower(text(k + 4)) == "space0";
      if (space0) {
        return errAt(k + 2, "register(b" + std::to_string(opt_.cbufferRegister) +
                                ") is already used; choose another cbuffer register");
      }
    }
    return std::nullopt;
  }

  const Function* enclosingFunction(size_t tok) const {
    for (const auto& f : functions_) {
      if (f.bodyOpen < tok && tok < f.bodyClose) return &f;
    }
    return nullptr;
  }

  // ---------------------------------------------------------------- geometry
  struct AppendSite {
    size_t open, close;  // absolute offsets of the '(' and ')' of Append(...)
    size_t appendOffset;
    std::string receiver;
    const Function* function;
  };

  std::optional<SpliceError> geometry(const std::vector<const Function*>& entries) {
    // The element type of the streams.
    const Param* entryStream = nullptr;
    for (const Function* f : entries) {
      for (const auto& p : f->params) {
        if (!p.streamElement.empty() && !entryStream) entryStream = &p;
      }
    }
    if (!entryStream) {
      return errAt(entries.front()->nameTok, "geometry entry point '" + opt_.entryPoint +
                                                 "' has no TriangleStream/LineStream/PointStream parameter");
    }
    const std::string elem = entryStream->streamElement;
    for (const auto& f : functions_) {
      for (const auto& p : f.params) {
        if (!p.streamElement.empty() && p.streamElement != elem) {
          return errAt(p.nameTok != npos ? p.nameTok : p.begin,
                       "streams of different element types ('" + elem + "' and '" + p.streamElement +
                           "') are not supported");
        }
      }
    }
    const StructDef* sd = findStruct(elem);
    if (!sd) {
      return errAt(entryStream->nameTok != npos ? entryStream->nameTok : entryStream->begin,
                   "the stream element type '" + elem +
                       "' is not a struct defined in this file (structs from #include files are not seen)");
    }
    std::optional<std::string> path = positionPath(elem);
    if (!path) return errAt(sd->nameTok, "struct '" + elem + "' has no member with semantic SV_Position");
    Shift shift{elem, std::string(kPrefix) + "_shift_" + elem, *path};

    // Names that are not streams: AppendStructuredBuffer<T> objects.
    std::set<std::string> buffers;
    for (size_t k = 0; k + 1 < toks_.size(); ++k) {
      if (!isWord(k, "AppendStructuredBuffer") || !isPunct(k + 1, '<')) continue;
      size_t t = k + 1;
      int depth = 0;
      do {
        if (isPunct(t, '<')) ++depth;
        if (isPunct(t, '>')) --depth;
        ++t;
      } while (t < toks_.size() && depth > 0);
      if (isIdent(t)) buffers.insert(std::string(text(t)));
    }
    auto isBufferReceiver = [&](const std::string& recv, const Function* f) {
      if (f) {
        for (const auto& p : f->params) {
          if (p.name == recv) return p.streamElement.empty() && p.typeName == "AppendStructuredBuffer";
        }
      }
      return buffers.count(recv) != 0;
    };

    std::vector<const Function*> candidates(entries.begin(), entries.end());
    // Append calls in function bodies (and anywhere else outside directives).
    for (size_t k = 0; k + 2 < toks_.size(); ++k) {
      if (!isPunct(k, '.') || !isWord(k + 1, "Append") || !isPunct(k + 2, '(')) continue;
      const Function* f = enclosingFunction(k);
      std::string recv;
      if (k > 0 && isIdent(k - 1) && !(k > 1 && isPunct(k - 2, '.'))) recv = std::string(text(k - 1));
      if (!recv.empty() && isBufferReceiver(recv, f)) continue;
      size_t close = match_[k + 2];
      if (close == k + 3) return errAt(k + 1, "Append() without an argument");
      for (size_t t = k + 3; t < close; ++t) {
        if (isPunct(t, '(') || isPunct(t, '[') || isPunct(t, '{')) t = match_[t];
        else if (isPunct(t, ',')) return errAt(k + 1, "Append() with more than one argument");
      }
      addEdit(toks_[k + 2].end, 0, shift.function + "(");
      addEdit(toks_[close].begin, 0, ")");
      ++sites_;
      if (f) candidates.push_back(f);
    }
    // Append calls inside #define bodies: the functions that use such a macro need the helper too.
    std::set<std::string> appendMacros;
    for (const auto& d : directives_) {
      if (d.name != "define" || d.bodyBegin >= d.end) continue;
      Scanner sub(s_, d.bodyBegin, d.end, false);
      if (sub.run()) continue;
      const auto& st = sub.tokens;
      auto stext = [&](size_t k) { return std::string_view(s_).substr(st[k].begin, st[k].end - st[k].begin); };
      auto spunct = [&](size_t k, char c) {
        return k < st.size() && st[k].kind == TokKind::Punct && s_[st[k].begin] == c;
      };
      for (size_t k = 0; k + 2 < st.size(); ++k) {
        if (!spunct(k, '.') || stext(k + 1) != "Append" || !spunct(k + 2, '(')) continue;
        if (k > 0 && st[k - 1].kind == TokKind::Ident && buffers.count(std::string(stext(k - 1)))) continue;
        int depth = 0;
        size_t close = npos;
        for (size_t t = k + 2; t < st.size(); ++t) {
          if (spunct(t, '(')) ++depth;
          if (spunct(t, ')') && --depth == 0) {
            close = t;
            break;
          }
        }
        if (close == npos || close == k + 3) continue;
        addEdit(st[k + 2].end, 0, shift.function + "(");
        addEdit(st[close].begin, 0, ")");
        ++sites_;
        appendMacros.insert(d.macroName);
      }
    }
    if (!appendMacros.empty()) {
      for (const auto& f : functions_) {
        for (size_t t = f.bodyOpen; t < f.bodyClose; ++t) {
          if (isIdent(t) && appendMacros.count(std::string(text(t)))) {
            candidates.push_back(&f);
            break;
          }
        }
      }
    }
    if (sites_ == 0) {
      return errAt(entries.front()->nameTok, "geometry shader '" + opt_.entryPoint + "' has no Append call");
    }

    size_t first = npos;
    for (const Function* f : candidates) first = std::min(first, toks_[f->declBegin].begin);
    size_t structEnd = toks_[sd->endTok].end;
    if (first < structEnd) {
      return errAt(sd->nameTok, "struct '" + elem + "' is defined after its first use at " + where(first));
    }
    if (auto err = checkConflicts({opt_.cbufferName, opt_.eyeSignName, opt_.separationName,
                                   opt_.convergenceName, shift.function})) {
      return err;
    }
    insertBlockBefore(first, structEnd, preambleText({shift}));
    return std::nullopt;
  }

  // ---------------------------------------------------------------- domain
  std::optional<SpliceError> domain(const std::vector<const Function*>& entries) {
    std::vector<Shift> shifts;
    auto needShift = [&](const std::string& type, const std::string& access) -> const Shift& {
      std::string fn = std::string(kPrefix) + "_shift_" + (access.empty() ? std::string("position") : type);
      for (const auto& sh : shifts) {
        if (sh.function == fn) return sh;
      }
      shifts.push_back({access.empty() ? std::string("float4") : type, fn, access});
      return shifts.back();
    };
    std::string mono = opt_.entryPoint + "_" + kPrefix + "_mono";
    struct Plan {
      const Function* f;
      std::string returnShift;  // helper for the return value, "" if none
      std::vector<std::pair<std::string, std::string>> outShifts;  // (param, helper)
    };
    std::vector<Plan> plans;
    for (const Function* f : entries) {
      Plan plan{f, {}, {}};
      // Return type: identifiers between the attributes and the name.
      std::string retType;
      for (size_t t = f->typeBegin; t < f->nameTok; ++t) {
        if (isPunct(t, '<')) break;
        if (isIdent(t) && !modifierWords().count(std::string(text(t)))) retType = std::string(text(t));
      }
      std::string retSemantic = f->semTok != npos ? lower(text(f->semTok)) : "";
      if (retSemantic == "sv_position" && isFloat4Like(retType)) {
        plan.returnShift = needShift(retType, "").function;
      } else if (auto path = positionPath(retType)) {
        plan.returnShift = needShift(retType, *path).function;
      }
      for (const auto& p : f->params) {
        if (p.name.empty()) return errAt(p.begin, "parameter without a name");
        if (!p.isOut) continue;
        if (lower(p.semantic) == "sv_position" && isFloat4Like(p.typeName)) {
          plan.outShifts.push_back({p.name, needShift(p.typeName, "").function});
        } else if (auto path = positionPath(p.typeName)) {
          plan.outShifts.push_back({p.name, needShift(p.typeName, *path).function});
        }
      }
      if (plan.returnShift.empty() && plan.outShifts.empty()) {
        return errAt(f->nameTok, "domain entry point '" + opt_.entryPoint +
                                     "' has no SV_Position output (return value, struct member or out parameter)");
      }
      plans.push_back(std::move(plan));
    }
    std::vector<std::string> ours = {opt_.cbufferName, opt_.eyeSignName, opt_.separationName, opt_.convergenceName,
                                     mono};
    for (const auto& sh : shifts) ours.push_back(sh.function);
    if (auto err = checkConflicts(ours)) return err;

    // Preamble before the first entry definition, after the structs it needs.
    size_t first = npos;
    for (const Function* f : entries) first = std::min(first, toks_[f->declBegin].begin);
    size_t notBefore = 0;
    for (const auto& sh : shifts) {
      if (const StructDef* sd = findStruct(sh.type)) notBefore = std::max(notBefore, toks_[sd->endTok].end);
    }
    insertBlockBefore(first, notBefore, preambleText(shifts));

    std::string nl = newline();
    for (const auto& plan : plans) {
      const Function* f = plan.f;
      // Attributes move to the wrapper; a comment keeps the line structure of the original.
      std::string attrs;
      for (const auto& a : f->attrs) {
        std::string at = tokSpan(a.open, a.close);
        attrs += at + nl;
        size_t b = toks_[a.open].begin;
        addEdit(b, at.size(), at.find("*/") == npos ? "/* " + at + " */" : std::string());
      }
      addEdit(toks_[f->nameTok].begin, toks_[f->nameTok].end - toks_[f->nameTok].begin, mono);

      std::string retType = f->typeBegin < f->nameTok ? tokSpan(f->typeBegin, f->nameTok - 1) : "void";
      bool isVoid = retType == "void";
      std::string args;
      for (const auto& p : f->params) args += (args.empty() ? "" : ", ") + p.name;
      std::string call = mono + "(" + args + ")";
      std::string body;
      std::string ind = "    ";
      if (!isVoid && !plan.returnShift.empty() && plan.outShifts.empty()) {
        body = ind + "return " + plan.returnShift + "(" + call + ");" + nl;
      } else {
        std::string result = std::string(kPrefix) + "_result";
        body = isVoid ? ind + call + ";" + nl : ind + retType + " " + result + " = " + call + ";" + nl;
        if (!plan.returnShift.empty()) body += ind + result + " = " + plan.returnShift + "(" + result + ");" + nl;
        for (const auto& [param, helper] : plan.outShifts) body += ind + param + " = " + helper + "(" + param + ");" + nl;
        if (!isVoid) body += ind + "return " + result + ";" + nl;
      }
      std::string wrapper = "// stereoshift: entry point wrapper, shifts the clip position of '" + mono + "'" + nl;
      wrapper += attrs + retType + " " + opt_.entryPoint + tokSpan(f->paramOpen, f->paramClose);
      if (f->semTok != npos) wrapper += " : " + std::string(text(f->semTok));
      wrapper += nl + "{" + nl + body + "}" + nl;
      insertBlockAfter(f->bodyClose, wrapper);
      sites_ += static_cast<int>((plan.returnShift.empty() ? 0 : 1) + plan.outShifts.size());
    }
    return std::nullopt;
  }

  std::optional<SpliceError> runImpl() {
    if (auto err = checkOptions()) return err;
    Scanner scanner(s_, 0, s_.size(), true);
    if (auto err = scanner.run()) return err;
    toks_ = std::move(scanner.tokens);
    directives_ = std::move(scanner.directivesList);
    blockComments_ = std::move(scanner.blockComments);
    if (auto err = matchBrackets(s_, toks_, match_)) return err;
    if (auto err = parseTopLevel()) return err;
    std::vector<const Function*> entries;
    for (const auto& f : functions_) {
      if (text(f.nameTok) == opt_.entryPoint) entries.push_back(&f);
    }
    if (entries.empty()) return SpliceError{npos, "entry point '" + opt_.entryPoint + "' not found"};
    return opt_.geometry ? geometry(entries) : domain(entries);
  }

  const std::string& s_;
  const HlslSpliceOptions& opt_;
  std::vector<Token> toks_;
  std::vector<Directive> directives_;
  std::vector<Span> blockComments_;
  std::vector<size_t> match_;
  std::vector<Function> functions_;
  std::vector<StructDef> structs_;
  std::map<std::string, size_t> topNames_;  // file-scope name -> token
  std::vector<Edit> edits_;
  int sites_ = 0;
};

}  // namespace

HlslSpliceResult spliceHlslStereo(const std::string& source, const HlslSpliceOptions& options) {
  return Splicer(source, options).run();
}

}  // namespace stereoshift
