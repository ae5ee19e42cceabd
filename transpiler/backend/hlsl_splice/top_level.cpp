// The HLSL splice's top-level parser: see top_level.h.
#include "transpiler/backend/hlsl_splice/top_level.h"

#include <algorithm>

namespace stereoshift::hlsl_splice {

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

namespace {

class TopLevelParser {
 public:
  TopLevelParser(const TokenView& view, TopLevel& top)
      : v_(view), toks_(view.tokens), match_(view.match), functions_(top.functions), structs_(top.structs),
        topNames_(top.names) {}

  std::optional<SpliceError> parseTopLevel() {
    const size_t n = toks_.size();
    size_t i = 0;
    while (i < n) {
      if (isPunct(i, '[') && (!declBegin_ || afterAttrs_ == i)) {
        attrs_.push_back({i, match_[i]});
        if (!declBegin_) declBegin_ = i;
        i = match_[i] + 1;
        afterAttrs_ = i;
        continue;
      }
      if (isPunct(i, ';')) {
        reset();
        ++i;
        continue;
      }
      if (isPunct(i, '}')) {
        if (!namespaceOpeners_.count(match_[i])) return errAt(i, "unexpected '}' at file scope");
        reset();
        ++i;
        continue;
      }
      if (!declBegin_) declBegin_ = i;
      if (std::optional<size_t> next = parseStruct(i)) {
        i = *next;
      } else if (isWord(i, "cbuffer") || isWord(i, "tbuffer")) {
        i = parseBuffer(i);
      } else if (isWord(i, "namespace") && isIdent(i + 1) && isPunct(i + 2, '{')) {
        namespaceOpeners_.insert(i + 2);
        i += 3;
      } else if (isWord(i, "typedef")) {
        size_t semi = skipToSemicolon(i);
        if (semi > i + 1 && isIdent(semi - 1)) topNames_[std::string(text(semi - 1))] = semi - 1;
        i = semi < n && isPunct(semi, ';') ? semi + 1 : semi;
      } else {
        i = parseDeclaration(i);
      }
      reset();
    }
    return std::nullopt;
  }

 private:
  void reset() {
    declBegin_.reset();
    attrs_.clear();
    afterAttrs_ = npos;
  }

  // `struct Name { ... } [declarators];` (class, interface) at `i`: the token after it, or nullopt
  // when `i` starts no definition.
  std::optional<size_t> parseStruct(size_t i) {
    const size_t n = toks_.size();
    if (!((isWord(i, "struct") || isWord(i, "class") || isWord(i, "interface")) && isIdent(i + 1) &&
          (isPunct(i + 2, '{') || isPunct(i + 2, ':'))))
      return std::nullopt;
    size_t open = i + 2;
    while (open < n && !isPunct(open, '{') && !isPunct(open, ';')) ++open;
    if (open >= n || !isPunct(open, '{')) return std::nullopt;
    StructDef sd;
    sd.name = std::string(text(i + 1));
    sd.nameTok = i + 1;
    parseMembers(open, match_[open], sd.members);
    size_t semi = skipToSemicolon(match_[open] + 1);
    collectNames(match_[open] + 1, semi);
    sd.endTok = semi < n && isPunct(semi, ';') ? semi : match_[open];
    topNames_[sd.name] = sd.nameTok;
    structs_.push_back(std::move(sd));
    return semi < n && isPunct(semi, ';') ? semi + 1 : semi;
  }

  // `cbuffer Name [: register(b0)] { members };` at `i`: its members are file-scope names.
  size_t parseBuffer(size_t i) {
    const size_t n = toks_.size();
    if (isIdent(i + 1)) topNames_[std::string(text(i + 1))] = i + 1;
    size_t open = i + 1;
    while (open < n && !isPunct(open, '{') && !isPunct(open, ';')) ++open;
    if (open >= n || !isPunct(open, '{')) return open + 1;
    for (size_t k = open + 1; k < match_[open];) {
      size_t semi = skipToSemicolon(k);
      collectNames(k, std::min(semi, match_[open]));
      k = semi + 1;
    }
    i = match_[open] + 1;
    return isPunct(i, ';') ? i + 1 : i;
  }

  // A variable declaration, a prototype or a function definition at `i`: the token after it.
  size_t parseDeclaration(size_t i) {
    const size_t n = toks_.size();
    bool sawEquals = false;
    for (size_t k = i; k < n;) {
      if (isPunct(k, '(')) {
        if (k > i && isIdent(k - 1) && !sawEquals) {
          if (std::optional<size_t> next = parseFunction(k)) return *next;
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
        return isPunct(k, ';') ? k + 1 : k;
      }
      if (isPunct(k, '=')) sawEquals = true;
      ++k;
    }
    collectNames(i, n);
    return n;
  }

  // The function whose parameter list opens at `open`, when a body follows it (`) {` or
  // `) : SEMANTIC {`): the token after the body; nullopt for a prototype or a call.
  std::optional<size_t> parseFunction(size_t open) {
    size_t close = match_[open];
    size_t body = npos, semColon = npos, semTok = npos;
    if (isPunct(close + 1, '{')) {
      body = close + 1;
    } else if (isPunct(close + 1, ':') && isIdent(close + 2) && isPunct(close + 3, '{')) {
      semColon = close + 1;
      semTok = close + 2;
      body = close + 3;
    }
    if (body == npos) return std::nullopt;
    Function f;
    f.attrs = attrs_;
    f.declBegin = *declBegin_;
    f.typeBegin = attrs_.empty() ? *declBegin_ : attrs_.back().close + 1;
    f.nameTok = open - 1;
    f.paramOpen = open;
    f.paramClose = close;
    f.semColon = semColon;
    f.semTok = semTok;
    f.bodyOpen = body;
    f.bodyClose = match_[body];
    f.params = parseParams(open, close);
    topNames_[std::string(text(open - 1))] = open - 1;
    functions_.push_back(std::move(f));
    return match_[body] + 1;
  }

 public:
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

 private:
  std::string_view text(size_t k) const { return v_.text(k); }
  bool isPunct(size_t k, char c) const { return v_.isPunct(k, c); }
  bool isIdent(size_t k) const { return v_.isIdent(k); }
  bool isWord(size_t k, std::string_view w) const { return v_.isWord(k, w); }
  SpliceError errAt(size_t tok, std::string msg) const { return v_.errAt(tok, std::move(msg)); }
  size_t skipToSemicolon(size_t k) const { return v_.skipToSemicolon(k); }

  const TokenView& v_;
  const std::vector<Token>& toks_;
  const std::vector<size_t>& match_;
  std::vector<Function>& functions_;
  std::vector<StructDef>& structs_;
  std::map<std::string, size_t>& topNames_;
  // The declaration being read: where it began, its attributes, the token after them.
  std::optional<size_t> declBegin_;
  std::vector<Attr> attrs_;
  size_t afterAttrs_ = npos;
  std::set<size_t> namespaceOpeners_;
};

}  // namespace

std::optional<SpliceError> parseTopLevel(const TokenView& view, TopLevel& top) {
  return TopLevelParser(view, top).parseTopLevel();
}

const StructDef* TopLevel::findStruct(const std::string& name) const {
  for (const auto& sd : structs) {
    if (sd.name == name) return &sd;
  }
  return nullptr;
}

// Member path (".a.b") of the SV_Position member of struct `name`, searching nested structs.
std::optional<std::string> TopLevel::positionPath(const std::string& name, int depth) const {
  const StructDef* sd = findStruct(name);
  if (!sd || depth > 8) return std::nullopt;
  for (const auto& m : sd->members) {
    if (isPositionSemantic(m.semantic)) return "." + m.name;
  }
  for (const auto& m : sd->members) {
    if (m.semantic.empty() && m.typeName != name) {
      if (auto sub = positionPath(m.typeName, depth + 1)) return "." + m.name + *sub;
    }
  }
  return std::nullopt;
}

const Function* TopLevel::enclosingFunction(size_t tok) const {
  for (const auto& f : functions) {
    if (f.bodyOpen < tok && tok < f.bodyClose) return &f;
  }
  return nullptr;
}

std::optional<SpliceError> checkConflicts(const TokenView& view, const TopLevel& top,
                                          const std::vector<std::string>& ours, uint32_t cbufferRegister,
                                          bool checkRegister) {
  for (const auto& name : ours) {
    if (name.empty()) continue;
    auto it = top.names.find(name);
    if (it != top.names.end()) {
      SpliceError err = view.errAt(it->second, "'" + name + "' is already declared at file scope (already stereo-injected?)");
      err.clash = true;
      return err;
    }
    for (const auto& d : view.directives) {
      if (d.name == "define" && d.macroName == name) {
        return SpliceError{d.begin, "'" + name + "' is already defined as a macro", true};
      }
    }
  }
  // register(b<N>) or register(b<N>, space0) already in use.
  for (size_t k = 0; checkRegister && k + 2 < view.tokens.size(); ++k) {
    if (!view.isWord(k, "register") || !view.isPunct(k + 1, '(') || !view.isIdent(k + 2)) continue;
    std::string reg = lower(view.text(k + 2));
    if (reg != "b" + std::to_string(cbufferRegister)) continue;
    bool space0 = true;
    if (view.isPunct(k + 3, ',') && view.isIdent(k + 4)) space0 = lower(view.text(k + 4)) == "space0";
    if (space0) {
      SpliceError err = view.errAt(k + 2, "register(b" + std::to_string(cbufferRegister) +
                                              ") is already used; choose another cbuffer register");
      err.clash = true;
      return err;
    }
  }
  return std::nullopt;
}

}  // namespace stereoshift::hlsl_splice
