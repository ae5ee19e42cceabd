// This turns the passes' decisions for a GLSL vertex, tessellation-evaluation or geometry shader into
// stereo GLSL of the same dialect by a source splice: see glsl_splice.h.
#include "transpiler/backend/glsl_splice.h"

#include "transpiler/source/lexer.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string_view>

namespace stereoshift {

namespace {

constexpr const char* kMonoSuffix = "_stereoshift_mono";
constexpr const char* kShiftHelper = "stereoshift_shiftPosition";
constexpr const char* kShiftedX = "stereoshift_x";
constexpr const char* kShiftedPosition = "stereoshift_shifted_position";

struct Word {
  size_t begin, end;
  std::string text;     // as spelled (line splices removed)
  std::string splices;  // the line splices inside it, kept by a rename
  bool inDefine = false;  // in a #define's body
};

// The identifiers and punctuation of `text` outside comments and outside directives other than
// #define (whose body is code: the macro's name and body are words, `define` is not), in order;
// numbers and string literals are skipped.
std::vector<Word> words(const std::string& text) {
  std::vector<Word> out;
  source::LexedText lexed(text);
  size_t defineName = std::string::npos;  // the `define` of the directive being read
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.kind == source::TokenKind::Directive) {
      defineName = t.directive == source::DirectiveKind::Define ? lexed.nextNonComment(k) : std::string::npos;
      continue;
    }
    if (t.inDirective() && (t.directive != source::DirectiveKind::Define || k == defineName)) continue;
    if (t.kind == source::TokenKind::Identifier || t.kind == source::TokenKind::Punctuation)
      out.push_back({t.begin, t.end, source::spelledString(text, t), source::splicesOf(text, t), t.inDirective()});
  }
  return out;
}


// When `p` (the position) is shifted: the condition of emitCutoffCondition, in its order.
std::string conditionText(const GlslSpliceOptions& spec, const std::string& p) {
  std::string stereo = spec.eyeSignName + " != 0.0";
  // isinf exists from GLSL 130 / ESSL 300; below, `abs(w) <= FLT_MAX` is false for inf and NaN alike
  // (a NaN w fails the other term anyway), so the condition is the same.
  bool hasIsinf = spec.es ? spec.version >= 300 : spec.version >= 130;
  std::string finite = hasIsinf ? "!isinf(" + p + ".w)" : "abs(" + p + ".w) <= 3.40282347e+38";
  switch (spec.cutoff) {
    case CutoffMode::Epsilon:
      return stereo + " && abs(" + p + ".w - 1.0) > " + glslFloatLiteral(spec.epsilon) + " && " + finite;
    case CutoffMode::Exact:
      return stereo + " && " + p + ".w != 1.0 && " + finite;
    case CutoffMode::None:
      break;
  }
  return stereo;
}

std::string shiftedX(const GlslSpliceOptions& spec, const std::string& p, bool fused) {
  std::string scale = spec.eyeSignName + " * " + spec.separationName;
  if (fused) return "fma(" + scale + ", " + p + ".w - " + spec.convergenceName + ", " + p + ".x)";
  return p + ".x + (" + scale + ") * (" + p + ".w - " + spec.convergenceName + ")";
}

// The statements that shift gl_Position under the cutoff and give the halo copies the shifted
// value, each line starting with `ind`. With `precise` (GLSL 400 / ESSL 320) the shifted x is a
// precise temporary, so no compiler contracts it differently in a depth pre-pass and the colour pass.
// `p` another vec4 than gl_Position: the same statements on it, no halo copies.
std::string shiftStatements(const GlslSpliceOptions& o, const std::string& ind, const std::string& nl,
                            const std::string& p = "gl_Position") {
  bool modern = glslHasPreciseAndFma(o.version, o.es);
  bool precise = modern && o.precise;
  std::string x = shiftedX(o, p, modern && o.fused), t;
  auto assign = [&](const std::string& at, const std::string& value) {
    if (!precise) return at + p + ".x = " + value + ";" + nl;
    return at + "precise float " + kShiftedX + " = " + value + ";" + nl + at + p + ".x = " + kShiftedX + ";" + nl;
  };
  if (o.form == ShiftForm::Select) {
    t += assign(ind, "(" + conditionText(o, p) + ") ? " + x + " : " + p + ".x");
  } else {
    t += ind + "if (" + conditionText(o, p) + ")" + nl + ind + "{" + nl;
    t += assign(ind + ind, x) + ind + "}" + nl;
  }
  if (p == "gl_Position")
    for (const auto& copy : o.haloCopies) t += ind + copy + " = " + p + ";" + nl;
  return t;
}

std::string declarationText(const GlslSpliceOptions& o, const std::string& nl) {
  std::string t;
  if (o.declarations.empty() && o.pushConstantMembers.empty())
    for (const std::string* name : {&o.eyeSignName, &o.separationName, &o.convergenceName})
      t += "uniform float " + *name + ";" + nl;
  for (const auto& line : o.declarations) t += line + nl;
  return t;
}

using Inserts = std::map<size_t, std::string>;  // offset -> text inserted there

// `source` with each insertion made at its offset.
std::string applyInserts(const std::string& source, const Inserts& inserts) {
  std::string text;
  size_t pos = 0;
  for (const auto& [at, insert] : inserts) {
    text.append(source, pos, at - pos);
    text += insert;
    pos = at;
  }
  text.append(source, pos, std::string::npos);
  return text;
}

bool isEmit(const std::string& word) { return word == "EmitVertex" || word == "EmitStreamVertex"; }

// Where each top-level item starts and whether a word is inside a function body, for the wraps.
struct Scopes {
  std::vector<size_t> itemStart;  // per word: the first word of the top-level declaration it is in
  std::vector<bool> inBody, parameter;  // per word: in a function body; in a parameter list at file scope
};

Scopes scopesOf(const std::vector<Word>& w) {
  Scopes s;
  size_t itemStart = 0;
  int depth = 0, parens = 0;
  std::vector<bool> functionBody;  // per open brace: whether it opens a function body
  bool inBody = false;
  for (size_t k = 0; k < w.size(); ++k) {
    const std::string& t = w[k].text;
    s.itemStart.push_back(itemStart);
    s.inBody.push_back(inBody);
    s.parameter.push_back(depth == 0 && parens > 0);
    if (w[k].inDefine) continue;
    if (t == "{") {
      size_t before = k;  // a macro's words between `)` and `{` are not the function's
      while (before > 0 && w[before - 1].inDefine) --before;
      functionBody.push_back(depth == 0 && before > 0 && w[before - 1].text == ")");
      inBody = inBody || functionBody.back();
      ++depth;
    } else if (t == "}" && depth > 0) {
      --depth;
      bool body = functionBody.back();
      functionBody.pop_back();
      if (body) inBody = false;
      if (depth == 0 && body) itemStart = k + 1;
    } else if (t == ";" && depth == 0) {
      itemStart = k + 1;
    } else if (t == "(" || t == ")") {
      parens += t == "(" ? 1 : -1;
    }
  }
  return s;
}

// `prototype` before the top-level item that holds word `k`, once per item.
void addPrototype(const std::vector<Word>& w, const Scopes& scopes, size_t k, const std::string& prototype,
                  Inserts& inserts) {
  size_t at = w[scopes.itemStart[k]].begin;
  if (inserts[at].find(prototype) == std::string::npos) inserts[at] = prototype + inserts[at];
}

// `function(` before word `first`, `)` after word `last`, the prototype before the item.
void wrap(const std::vector<Word>& w, const Scopes& scopes, size_t first, size_t last, const std::string& function,
          const std::string& prototype, Inserts& inserts) {
  inserts[w[first].begin] += function + "(";
  inserts[w[last].end] = ")" + inserts[w[last].end];
  addPrototype(w, scopes, first, prototype, inserts);
}

std::string markedPrototype(const std::string& declaration) {
  return "/* ---- stereoshift ---- */ " + declaration + "; /* ---- end stereoshift ---- */ ";
}

// Geometry shaders: the statements `EmitVertex();` / `EmitStreamVertex(n);` wrapped as
// `{ stereoshift_shiftPosition(); ... }`, and the helper's prototype before every top-level
// function that emits (each #if branch that defines one gets its own). Line numbers do not move.
bool wrapEmits(const std::string& source, const std::vector<Word>& w, std::string& text, GlslSpliceResult& result) {
  Inserts inserts;
  const std::string prototype = markedPrototype(std::string("void ") + kShiftHelper + "()");
  const Scopes scopes = scopesOf(w);
  for (size_t k = 0; k < w.size(); ++k) {
    const std::string& t = w[k].text;
    if (!isEmit(t)) continue;
    if (w[k].inDefine) {
      result.error = "the shader emits vertices inside a macro";
      return false;
    }
    if (k + 1 >= w.size() || w[k + 1].text != "(" || (k > 0 && w[k - 1].text == ".")) continue;
    int parens = 0;
    size_t close = k + 1;
    for (; close < w.size() && !w[close].inDefine; ++close) {
      if (w[close].text == "(") ++parens;
      if (w[close].text == ")" && --parens == 0) break;
    }
    if (!scopes.inBody[k] || close + 1 >= w.size() || w[close].text != ")" || w[close + 1].text != ";" ||
        w[close + 1].inDefine) {
      result.error = "`" + t + "` is not called as a statement of its own";
      return false;
    }
    inserts[w[k].begin] += std::string("{ ") + kShiftHelper + "(); ";
    inserts[w[close + 1].end] += " }";
    addPrototype(w, scopes, k, prototype, inserts);
    ++result.sites;
    k = close + 1;
  }
  if (result.sites == 0) {
    result.error = "the shader calls neither EmitVertex nor EmitStreamVertex in its own text";
    return false;
  }
  text = applyInserts(source, inserts);
  return true;
}

// Splits `a.b.c` into its names.
std::vector<std::string> accessParts(const std::string& access) {
  std::vector<std::string> parts;
  for (size_t from = 0;;) {
    size_t dot = access.find('.', from);
    parts.push_back(access.substr(from, dot - from));
    if (dot == std::string::npos) return parts;
    from = dot + 1;
  }
}

// The last word of `parts` (`a . b . c`) read from `k` on, or npos when the words there are not it.
size_t accessEnd(const std::vector<Word>& w, size_t k, const std::vector<std::string>& parts) {
  if (w[k].text != parts[0]) return std::string::npos;
  size_t last = k;
  for (size_t j = 1; j < parts.size(); ++j) {
    if (last + 2 >= w.size() || w[last + 1].text != "." || w[last + 2].text != parts[j]) return std::string::npos;
    last += 2;
  }
  return last;
}

// The word that closes the bracket opened at `open` (`(`, `[`, `{`), or npos.
size_t closing(const std::vector<Word>& w, size_t open) {
  const std::string opener = w[open].text, closer = opener == "(" ? ")" : opener == "[" ? "]" : "}";
  int depth = 0;
  for (size_t k = open; k < w.size() && !w[k].inDefine; ++k) {
    if (w[k].text == opener) ++depth;
    if (w[k].text == closer && --depth == 0) return k;
  }
  return std::string::npos;
}

// The last word of the postfix expression starting at `k` (a name, a call or constructor, a
// parenthesised expression, then member accesses, swizzles and indices), or npos.
size_t postfixEnd(const std::vector<Word>& w, size_t k) {
  if (k >= w.size() || w[k].inDefine) return std::string::npos;
  size_t end;
  if (w[k].text == "(") {
    end = closing(w, k);
  } else if (isIdentifierStart(w[k].text[0])) {
    end = k + 1 < w.size() && w[k + 1].text == "(" ? closing(w, k + 1) : k;
  } else {
    return std::string::npos;
  }
  while (end != std::string::npos && end + 1 < w.size()) {
    if (w[end + 1].text == "." && end + 2 < w.size() && isIdentifierStart(w[end + 2].text[0]))
      end += 2;
    else if (w[end + 1].text == "[")
      end = closing(w, end + 1);
    else
      break;
  }
  return end;
}

// The first part of a camera's access (`camera` of `camera.position`): the struct holding it.
std::string holderPart(const std::string& access) { return access.substr(0, access.find('.')); }
// The helper that returns a copy of that struct with this eye's camera in it.
std::string holderFunction(const std::string& access) { return "stereoshift_holder_" + holderPart(access); }

// Per-eye cameras: every read of a camera in a function body wrapped as `function(camera)`, the
// helper's prototype before each top-level function that reads it. Refused where the text is not
// plain enough to be sure every read is the camera's: a read in a macro, a local, parameter or
// other declaration of the same name, a struct holding the camera used whole.
bool wrapCameraReads(const std::vector<Word>& w, const Scopes& scopes, const GlslSpliceOptions& o, Inserts& inserts,
                     std::string& error) {
  const std::string highp = o.es ? "highp " : "";
  for (const auto& camera : o.cameras) {
    std::vector<std::string> parts = accessParts(camera.access);
    const std::string type = highp + (camera.inverseOf ? std::string("mat4") : camera.type);
    const std::string prototype = markedPrototype(type + " " + camera.function + "(" + type + " stereoshift_camera)");
    size_t reads = 0;
    for (size_t k = 0; k < w.size(); ++k) {
      if (w[k].text != parts[0] || (k > 0 && w[k - 1].text == ".")) continue;
      if (camera.inverseOf) {
        // `inverse(<matrix>)`: the call is wrapped; other reads of the matrix stay the mono view.
        size_t last = accessEnd(w, k, parts);
        bool call = k >= 2 && w[k - 1].text == "(" && w[k - 2].text == "inverse" && last != std::string::npos &&
                    last + 1 < w.size() && w[last + 1].text == ")";
        if (w[k].inDefine && call) {
          error = "inverse(" + camera.access + ") is written inside a macro";
          return false;
        }
        if (!call || !scopes.inBody[k]) continue;
        wrap(w, scopes, k - 2, last + 1, camera.function, prototype, inserts);
        ++reads;
        continue;
      }
      if (w[k].inDefine) {
        error = "the camera '" + camera.access + "' is named inside a macro";
        return false;
      }
      // A declaration of the name: the camera's own (a global, a block member), a struct's member
      // (read through `.`, never the camera), or a local or parameter that hides the camera.
      bool declared = k > 0 && isIdentifierStart(w[k - 1].text[0]) && w[k - 1].text != "return";
      if (declared && (scopes.inBody[k] || scopes.parameter[k])) {
        error = "a local or parameter named '" + parts[0] + "' hides the camera '" + camera.access + "'";
        return false;
      }
      if (declared || !scopes.inBody[k]) continue;
      size_t last = accessEnd(w, k, parts);
      if (last == std::string::npos) {
        if (k + 1 < w.size() && w[k + 1].text == ".") continue;  // another member
        // The struct holding the camera read whole: a copy of it with this eye's camera.
        if (!camera.holderType.empty() && parts.size() > 1 && !(k + 1 < w.size() && w[k + 1].text == "[")) {
          wrap(w, scopes, k, k, holderFunction(camera.access),
               markedPrototype(camera.holderType + " " + holderFunction(camera.access) + "(" + camera.holderType +
                               " stereoshift_holder)"),
               inserts);
          ++reads;
          continue;
        }
        error = "'" + parts[0] + "', which holds the camera '" + camera.access + "', is used whole";
        return false;
      }
      wrap(w, scopes, k, last, camera.function, prototype, inserts);
      ++reads;
    }
    if (reads == 0) {
      error = "the camera '" + camera.access + "' is not read in a function of the text";
      return false;
    }
  }
  return true;
}

// Unprojections: every `<matrix> * <operand>` in a function body wrapped, as many as the analysis
// fixed through that matrix (else the text and the analysis disagree on which product is which).
bool wrapUnprojections(const std::vector<Word>& w, const Scopes& scopes, const GlslSpliceOptions& o, Inserts& inserts,
                       std::string& error) {
  const std::string type = o.es ? "highp vec4" : "vec4";
  for (const auto& u : o.unprojections) {
    std::vector<std::string> parts = accessParts(u.matrix);
    const std::string prototype = markedPrototype(type + " " + u.function + "(" + type + " stereoshift_q)");
    int found = 0;
    std::vector<std::pair<size_t, size_t>> spans;
    for (size_t k = 0; k < w.size(); ++k) {
      if (w[k].text != parts[0] || (k > 0 && (w[k - 1].text == "." || w[k - 1].text == "*" || w[k - 1].text == "/")))
        continue;
      size_t last = accessEnd(w, k, parts);
      if (last == std::string::npos || last + 1 >= w.size() || w[last + 1].text != "*") continue;
      if (w[k].inDefine || !scopes.inBody[k]) {
        error = "the product through '" + u.matrix + "' is written in a macro or outside a function";
        return false;
      }
      size_t end = postfixEnd(w, last + 2);
      if (end == std::string::npos) {
        error = "the operand of the product through '" + u.matrix + "' is not a plain expression";
        return false;
      }
      spans.push_back({k, end});
      ++found;
    }
    if (found != u.products) {
      error = "the text has " + std::to_string(found) + " product(s) `" + u.matrix + " * ...`, the analysis fixed " +
              std::to_string(u.products);
      return false;
    }
    for (const auto& [first, last] : spans) wrap(w, scopes, first, last, u.function, prototype, inserts);
  }
  return true;
}

// The shader's own push-constant block (`layout(push_constant) uniform B { ... } pc;`) extended by
// the eye parameters: one marked insertion before its closing brace. Refused where the text does not
// show one such block plainly (none, several under #if branches, one inside a macro).
bool extendPushConstantBlock(const std::vector<Word>& w, const GlslSpliceOptions& o, Inserts& inserts,
                             std::string& error) {
  if (o.pushConstantMembers.empty()) return true;
  std::vector<size_t> blocks;
  for (size_t k = 0; k < w.size(); ++k) {
    if (w[k].text != "push_constant") continue;
    if (w[k].inDefine) {
      error = "the push-constant block is declared inside a macro";
      return false;
    }
    blocks.push_back(k);
  }
  if (blocks.size() != 1) {
    error = "the text declares " + std::to_string(blocks.size()) + " push-constant blocks, the eye parameters join one";
    return false;
  }
  size_t open = blocks[0];
  while (open < w.size() && w[open].text != "{" && w[open].text != ";") ++open;
  size_t close = open < w.size() && w[open].text == "{" ? closing(w, open) : std::string::npos;
  if (close == std::string::npos) {
    error = "the push-constant block has no plain `{ ... }` in the text";
    return false;
  }
  std::string members;
  for (const auto& member : o.pushConstantMembers) members += member + " ";
  inserts[w[close].begin] += "/* ---- stereoshift ---- */ " + members + "/* ---- end stereoshift ---- */ ";
  return true;
}

// Whether the words after a name's postfix end `end` assign it by a compound operator or step it
// (`+=`, `<<=`, `++`), which a plain `=` is not.
bool compoundAssigned(const std::vector<Word>& w, size_t k, size_t end) {
  auto at = [&](size_t i) { return i < w.size() ? w[i].text : std::string(); };
  const std::string op = at(end + 1);
  if (op.size() == 1 && std::string("+-*/%&|^").find(op[0]) != std::string::npos && at(end + 2) == "=") return true;
  if ((op == "<" || op == ">") && at(end + 2) == op && at(end + 3) == "=") return true;
  if ((op == "+" || op == "-") && at(end + 2) == op) return true;
  return k >= 2 && (w[k - 1].text == "+" || w[k - 1].text == "-") && w[k - 2].text == w[k - 1].text;
}

// The one assignment `name = <expression>` of the text, as the words of `=` and of the `;` or `,`
// that ends the expression; nullopt with `error` set where the text does not show that one
// assignment plainly: a second one (the name declared again elsewhere, say), a compound one, a
// member or element assigned, the name in a macro. `what` names the value in the message.
std::optional<std::pair<size_t, size_t>> soleAssignment(const std::vector<Word>& w, const Scopes& scopes,
                                                        const std::string& name, const std::string& what,
                                                        std::string& error) {
  std::vector<size_t> assignments;
  for (size_t k = 0; k < w.size(); ++k) {
    if (w[k].text != name || (k > 0 && w[k - 1].text == ".")) continue;
    if (w[k].inDefine) {
      error = "the " + what + " '" + name + "' is named inside a macro";
      return std::nullopt;
    }
    size_t end = postfixEnd(w, k);
    if (end == std::string::npos) continue;
    bool assigns = end + 1 < w.size() && w[end + 1].text == "=" && !(end + 2 < w.size() && w[end + 2].text == "=");
    if (compoundAssigned(w, k, end) || (assigns && end != k)) {
      error = "the " + what + " '" + name + "' is changed after its assignment in the text";
      return std::nullopt;
    }
    if (assigns) assignments.push_back(k);
  }
  if (assignments.size() != 1 || !scopes.inBody[assignments[0]]) {
    error = "the text assigns the " + what + " '" + name + "' " + std::to_string(assignments.size()) +
            " times in its functions, the analysis saw one assignment";
    return std::nullopt;
  }
  size_t equals = assignments[0] + 1, stop = equals + 1;
  for (int depth = 0; stop < w.size() && !w[stop].inDefine; ++stop) {
    const std::string& t = w[stop].text;
    if (t == "(" || t == "[" || t == "{") ++depth;
    if (t == ")" || t == "]" || t == "}") --depth;
    if (depth <= 0 && (t == ";" || t == "," || depth < 0)) break;
  }
  if (stop >= w.size() || (w[stop].text != ";" && w[stop].text != ",")) {
    error = "the assignment of the " + what + " '" + name + "' does not end plainly";
    return std::nullopt;
  }
  return std::make_pair(equals, stop);
}

// View rays: the right-hand side of the one assignment to the local the analysis names, wrapped in
// the helper (the words of `source` around it kept: comments stay outside the call).
bool wrapViewRays(const std::string& source, const std::vector<Word>& w, const Scopes& scopes,
                  const GlslSpliceOptions& o, Inserts& inserts, std::string& error) {
  if (o.viewRays.empty()) return true;
  source::LexedText lexed(source);
  const std::string highp = o.es ? "highp " : "";
  for (const auto& r : o.viewRays) {
    const std::string type = highp + r.type;
    const std::string prototype = markedPrototype(type + " " + r.function + "(" + type + " stereoshift_p)");
    auto assignment = soleAssignment(w, scopes, r.local, "view-ray position", error);
    if (!assignment) return false;
    auto [equals, stop] = *assignment;
    size_t begin = std::string::npos, finish = std::string::npos;
    for (size_t t = 0; t < lexed.size(); ++t) {
      const source::Token& token = lexed[t];
      if (token.kind == source::TokenKind::Comment || token.begin < w[equals].end || token.end > w[stop].begin) continue;
      if (begin == std::string::npos) begin = token.begin;
      finish = token.end;
    }
    if (begin == std::string::npos) {
      error = "the assignment of the view-ray position '" + r.local + "' has no expression";
      return false;
    }
    inserts[begin] += r.function + "(";
    inserts[finish] = ")" + inserts[finish];
    addPrototype(w, scopes, equals - 1, prototype, inserts);
  }
  return true;
}

// Derived halo outputs: in the one assignment of each, every read of the position by one of its
// names goes through the shift.
bool wrapDerivedHalos(const std::vector<Word>& w, const Scopes& scopes, const GlslSpliceOptions& o, Inserts& inserts,
                      std::string& error) {
  const std::string type = o.es ? "highp vec4" : "vec4";
  const std::string prototype = markedPrototype(type + " " + kShiftedPosition + "(" + type + " stereoshift_p)");
  for (const auto& d : o.derivedHalos) {
    auto assignment = soleAssignment(w, scopes, d.output, "output computed from the position", error);
    if (!assignment) return false;
    int reads = 0;
    for (size_t k = assignment->first + 1; k < assignment->second; ++k) {
      if (k > 0 && w[k - 1].text == ".") continue;
      if (std::find(d.positionNames.begin(), d.positionNames.end(), w[k].text) == d.positionNames.end()) continue;
      wrap(w, scopes, k, k, kShiftedPosition, prototype, inserts);
      ++reads;
    }
    if (reads == 0) {
      error = "the assignment of '" + d.output + "' reads the position by no name the analysis saw";
      return false;
    }
  }
  return true;
}

std::string helperDefinitions(const GlslSpliceOptions& o, const std::string& ind, const std::string& nl) {
  const std::string highp = o.es ? "highp " : "";
  std::string t;
  for (const auto& c : o.cameras) {
    if (c.inverseOf) {
      // The inverse view's translation column is the camera centre: moved to this eye's.
      t += highp + "mat4 " + c.function + "(" + highp + "mat4 stereoshift_camera)" + nl + "{" + nl + ind +
           "stereoshift_camera[3] = stereoshift_camera[3] + vec4(" + c.offset + ", 0.0);" + nl + ind +
           "return stereoshift_camera;" + nl + "}" + nl;
      continue;
    }
    std::string offset = c.type == "vec4" ? "vec4(" + c.offset + ", 0.0)" : c.offset;
    t += highp + c.type + " " + c.function + "(" + highp + c.type + " stereoshift_camera)" + nl + "{" + nl + ind +
         "return stereoshift_camera + " + offset + ";" + nl + "}" + nl;
    if (!c.holderType.empty()) {
      // The holder struct read whole: the copy's camera member through the helper above.
      const std::string member = c.access.substr(holderPart(c.access).size());  // `.position`
      t += c.holderType + " " + holderFunction(c.access) + "(" + c.holderType + " stereoshift_holder)" + nl + "{" + nl +
           ind + "stereoshift_holder" + member + " = " + c.function + "(stereoshift_holder" + member + ");" + nl +
           ind + "return stereoshift_holder;" + nl + "}" + nl;
    }
  }
  const std::string scale = "(" + o.eyeSignName + " * " + o.separationName + ")";
  for (const auto& u : o.unprojections) {
    std::string value;
    if (u.reprojection) {
      // Back to this eye's screen: the shift of the clip position (docs/stereo-math.md section 1).
      bool fused = glslHasPreciseAndFma(o.version, o.es) && o.fused;
      value = "vec4(" + shiftedX(o, "stereoshift_q", fused) + ", stereoshift_q.yzw)";
    } else {
      value = "stereoshift_q - " + u.matrix + "[0] * (" + scale + " * (1.0 - " + o.convergenceName + " * stereoshift_q.w))";
    }
    t += highp + "vec4 " + u.function + "(" + highp + "vec4 stereoshift_q)" + nl + "{" + nl + ind + "return " +
         o.eyeSignName + " != 0.0 ? " + value + " : stereoshift_q;" + nl + "}" + nl;
  }
  if (!o.derivedHalos.empty()) {
    // The position as the shift leaves it, for the outputs computed from it.
    t += highp + "vec4 " + kShiftedPosition + "(" + highp + "vec4 stereoshift_p)" + nl + "{" + nl +
         shiftStatements(o, ind, nl, "stereoshift_p") + ind + "return stereoshift_p;" + nl + "}" + nl;
  }
  for (const auto& r : o.viewRays) {
    // The eye depth is |z| for either handedness (deferred_unprojection_pass.cpp).
    t += highp + r.type + " " + r.function + "(" + highp + r.type + " stereoshift_p)" + nl + "{" + nl + ind + "if (" +
         o.eyeSignName + " != 0.0)" + nl + ind + ind + "stereoshift_p.x = stereoshift_p.x - (" + scale +
         " * (abs(stereoshift_p.z) - " + o.convergenceName + ")) * " + r.inverseScale + ";" + nl + ind +
         "return stereoshift_p;" + nl + "}" + nl;
  }
  return t;
}

}  // namespace

std::string glslFloatLiteral(float value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(value));
  std::string lit = buf;
  if (lit.find_first_of(".eEn") == std::string::npos) lit += ".0";
  return lit;
}

bool glslHasPreciseAndFma(int version, bool es) { return es ? version >= 320 : version >= 400; }

std::vector<std::string> exactPositionCopies(const std::string& source) {
  std::vector<Word> w = words(source);
  std::map<std::string, bool> exact;  // name -> every assignment seen is `name = gl_Position;`
  for (size_t k = 0; k + 1 < w.size(); ++k) {
    if (!isIdentifierStart(w[k].text[0]) || w[k].text == "gl_Position") continue;
    bool assigned = w[k + 1].text == "=" && !(k + 2 < w.size() && w[k + 2].text == "=") &&
                    !(k > 0 && (w[k - 1].text == "." || w[k - 1].text == "]"));
    if (!assigned) continue;
    bool copy = k + 3 < w.size() && w[k + 2].text == "gl_Position" && w[k + 3].text == ";";
    auto [it, fresh] = exact.emplace(w[k].text, copy);
    if (!fresh) it->second = it->second && copy;
  }
  std::vector<std::string> out;
  for (const auto& [name, isCopy] : exact)
    if (isCopy) out.push_back(name);
  return out;
}

// The extensions the edits need, in a marked block after the #version line (before any code, as
// GLSL wants #extension); false where the text has no #version line.
bool insertExtensions(const std::string& source, const GlslSpliceOptions& o, const std::string& nl, Inserts& inserts,
                      std::string& error) {
  if (o.extensions.empty()) return true;
  source::LexedText lexed(source);
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.kind != source::TokenKind::Directive || t.directive != source::DirectiveKind::Version) continue;
    size_t end = source.find('\n', t.begin);
    if (end == std::string::npos) break;
    std::string block = "// ---- stereoshift: extensions (injected) ----" + nl;
    for (const auto& name : o.extensions) block += "#extension " + name + " : require" + nl;
    inserts[end + 1] += block + "// ---- end stereoshift ----" + nl;
    return true;
  }
  error = "the text has no #version line to put `#extension " + o.extensions.front() + "` after";
  return false;
}

GlslSpliceResult spliceGlslStereo(const std::string& original, const GlslSpliceOptions& options) {
  GlslSpliceResult result;
  std::string nl = original.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  std::vector<Word> originalWords = words(original);
  std::set<std::string> helpers;
  for (const auto& c : options.cameras) {
    helpers.insert(c.function);
    if (!c.holderType.empty()) helpers.insert(holderFunction(c.access));
  }
  for (const auto& u : options.unprojections) helpers.insert(u.function);
  for (const auto& r : options.viewRays) helpers.insert(r.function);
  if (!options.derivedHalos.empty()) helpers.insert(kShiftedPosition);
  for (const auto& word : originalWords)
    if (helpers.count(word.text)) {
      result.error = "the shader already uses the name `" + word.text + "` (is it converted already?)";
      return result;
    }
  // The wraps first: every later edit reads the text with them (they add no `main`, no emit).
  std::string source = original;
  if (!helpers.empty() || !options.pushConstantMembers.empty() || !options.extensions.empty()) {
    Scopes scopes = scopesOf(originalWords);
    Inserts inserts;
    if (!wrapCameraReads(originalWords, scopes, options, inserts, result.error) ||
        !wrapUnprojections(originalWords, scopes, options, inserts, result.error) ||
        !wrapViewRays(original, originalWords, scopes, options, inserts, result.error) ||
        !wrapDerivedHalos(originalWords, scopes, options, inserts, result.error) ||
        !extendPushConstantBlock(originalWords, options, inserts, result.error) ||
        !insertExtensions(original, options, nl, inserts, result.error))
      return result;
    source = applyInserts(original, inserts);
  }
  if (!options.shift) {
    std::string t = source.empty() || source.back() == '\n' ? "" : nl;
    t += "// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----" + nl;
    t += declarationText(options, nl) + helperDefinitions(options, "    ", nl) + "// ---- end stereoshift ----" + nl;
    result.text = source + t;
    result.ok = true;
    return result;
  }
  std::vector<Word> w = words(source);
  const std::string& entry = options.entryPoint;
  const std::string monoMain = entry + kMonoSuffix;
  for (const auto& word : w)
    for (const std::string& ours : {monoMain, std::string(kShiftHelper), std::string(kShiftedX)})
      if (word.text == ours) {
        result.error = "the shader already uses the name `" + ours + "` (is it converted already?)";
        return result;
      }
  const std::string ind = "    ";
  std::string text;
  std::string t;
  if (options.stage == Stage::Geometry) {
    if (!wrapEmits(source, w, text, result)) return result;
    if (!text.empty() && text.back() != '\n') t += nl;
    t += "// ---- stereoshift: stereo parameters and clip-space shift (injected) ----" + nl;
    t += declarationText(options, nl) + helperDefinitions(options, ind, nl);
    t += std::string("void ") + kShiftHelper + "()" + nl + "{" + nl + shiftStatements(options, ind, nl) + "}" + nl;
  } else {
    size_t pos = 0;
    for (const auto& word : w) {
      if (word.text != entry) continue;
      text.append(source, pos, word.begin - pos);
      text += monoMain + word.splices;  // a `main` written across a line splice keeps its lines
      pos = word.end;
      ++result.sites;
    }
    text.append(source, pos, std::string::npos);
    if (result.sites == 0) {
      result.error = "the shader defines no `" + entry + "` in its own text";
      return result;
    }
    result.sites = 1;
    if (!text.empty() && text.back() != '\n') t += nl;
    t += "// ---- stereoshift: stereo parameters and clip-space shift (injected) ----" + nl;
    t += declarationText(options, nl) + helperDefinitions(options, ind, nl);
    t += "void " + entry + "()" + nl + "{" + nl + ind + monoMain + "();" + nl + shiftStatements(options, ind, nl) + "}" + nl;
  }
  t += "// ---- end stereoshift ----" + nl;
  result.text = text + t;
  result.ok = true;
  return result;
}

}  // namespace stereoshift
