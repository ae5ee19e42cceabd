// See hlsl_lift.h.
#include "transpiler/frontend/hlsl_lift.h"

#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/source/lexer.h"

#include <cctype>
#include <map>
#include <string_view>
#include <vector>

namespace stereoshift {

namespace {

// System values glslang maps to built-ins only without an index, which D3D allows (index 0 is the
// same value) and decompilers always write: `o0 : SV_POSITION0`, `v2 : SV_VertexID0`.
bool isUnindexedSystemValue(std::string_view upper) {
  for (std::string_view name : {"SV_POSITION", "SV_VERTEXID", "SV_INSTANCEID", "SV_ISFRONTFACE", "SV_PRIMITIVEID",
                                "SV_SAMPLEINDEX", "SV_RENDERTARGETARRAYINDEX", "SV_VIEWPORTARRAYINDEX",
                                "SV_GSINSTANCEID", "SV_OUTPUTCONTROLPOINTID", "SV_DOMAINLOCATION",
                                "SV_DISPATCHTHREADID", "SV_GROUPID", "SV_GROUPTHREADID", "SV_GROUPINDEX", "SV_COVERAGE"})
    if (upper == name) return true;
  return false;
}

// The components of a matrix swizzle with two or more of them (`_m00_m10_m20_m30`, zero-based, or
// `_11_21_31_41`, one-based), each as its own single-component swizzle (`_m00`); empty when `name`
// is not one. One spelling per swizzle, as HLSL requires.
std::vector<std::string> matrixSwizzleComponents(std::string_view name) {
  std::vector<std::string> parts;
  if (name.size() < 4 || name[0] != '_') return parts;
  const bool zeroBased = name[1] == 'm';
  const size_t step = zeroBased ? 4 : 3;
  const char low = zeroBased ? '0' : '1', high = zeroBased ? '3' : '4';
  if (name.size() % step != 0) return {};
  for (size_t at = 0; at < name.size(); at += step) {
    std::string_view part = name.substr(at, step);
    if (part[0] != '_' || (zeroBased && part[1] != 'm')) return {};
    char row = part[step - 2], column = part[step - 1];
    if (row < low || row > high || column < low || column > high) return {};
    parts.emplace_back(part);
  }
  if (parts.size() < 2 || parts.size() > 4) return {};
  return parts;
}

// The scalar type of an HLSL matrix type name (`float4x3` -> "float", `min16float4x4` ->
// "min16float"); empty when `type` is not one.
std::string matrixScalarType(std::string_view type) {
  if (type.size() < 4 || type[type.size() - 2] != 'x') return {};
  char rows = type[type.size() - 3], columns = type[type.size() - 1];
  if (rows < '1' || rows > '4' || columns < '1' || columns > '4') return {};
  std::string_view scalar = type.substr(0, type.size() - 3);
  for (std::string_view known : {"float", "half", "double", "int", "uint", "bool", "dword", "min16float",
                                 "min10float", "min16int", "min12int", "min16uint"})
    if (scalar == known) return std::string(scalar);
  return {};
}

// The scalar type of every matrix declared as `TYPEnxm NAME` (cbuffer members, struct members,
// locals, parameters), by name; a name declared with two types maps to the first.
std::map<std::string, std::string, std::less<>> matrixDeclarations(const source::LexedText& lexed) {
  std::map<std::string, std::string, std::less<>> scalars;
  for (size_t k = 0; k < lexed.size(); ++k) {
    if (!lexed.isIdentifier(k) || !lexed[k].isCode()) continue;
    std::string scalar = matrixScalarType(lexed.text(k));
    if (scalar.empty()) continue;
    size_t name = lexed.nextNonComment(k);
    if (lexed.isIdentifier(name)) scalars.emplace(std::string(lexed.text(name)), scalar);
  }
  return scalars;
}

// Where the receiver of the member access at `dot` begins: the token index of the first token of
// the postfix chain before it (`World`, `Bones[r0.x]`, `Frame.Camera.ViewProj`), or `dot` when the
// chain is not one of names, member accesses and indexing (a call, a parenthesised expression).
// `lastName`: the chain's last name, the matrix's own (`Bones[i]` -> Bones, `Frame.ViewProj` -> ViewProj).
size_t receiverBegin(const source::LexedText& lexed, size_t dot, size_t* lastName) {
  size_t k = dot;
  *lastName = dot;
  while (k > 0) {
    size_t before = k - 1;
    while (before > 0 && lexed[before].kind == source::TokenKind::Comment) --before;
    if (lexed.isIdentifier(before)) {
      if (*lastName == dot) *lastName = before;
      k = before;
      size_t prior = k;
      while (prior > 0 && lexed[prior - 1].kind == source::TokenKind::Comment) --prior;
      if (prior > 0 && lexed.isPunct(prior - 1, '.')) {
        k = prior - 1;
        continue;
      }
      return k;
    }
    if (!lexed.isPunct(before, ']')) return dot;
    int depth = 0;
    size_t open = before;
    for (;; --open) {
      if (lexed.isPunct(open, ']')) ++depth;
      if (lexed.isPunct(open, '[') && --depth == 0) break;
      if (open == 0) return dot;
    }
    k = open;
  }
  return dot;
}

// Whether the token at `k` starts an assignment (`=`, `+=`, `<<=`, ...; not `==`): the expression
// before it is written, not read.
bool startsAssignment(const source::LexedText& lexed, size_t k) {
  if (lexed.isPunct(k, '=')) return !lexed.isPunctPair(k, "==");
  for (char op : {'+', '-', '*', '/', '%', '&', '|', '^'})
    if (lexed.isPunct(k, op) && lexed.isPunct(k + 1, '=') && lexed[k].end == lexed[k + 1].begin) return true;
  return lexed.isPunct(k, '<') || lexed.isPunct(k, '>')
             ? lexed.isPunct(k + 1, lexed.text(k)[0]) && lexed.isPunct(k + 2, '=') && lexed[k + 2].begin == lexed[k + 1].end
             : false;
}

// Parameter modifiers that may stand between a parameter list's `(` or `,` and the type.
bool isParameterModifier(std::string_view word) {
  for (std::string_view m : {"in", "out", "inout", "uniform", "const", "precise", "linear", "centroid",
                             "nointerpolation", "noperspective", "sample", "point", "line", "triangle",
                             "lineadj", "triangleadj", "vertices", "primitives", "indices", "payload"})
    if (word == m) return true;
  return false;
}

// The non-comment token before `k`, or lexed.size() when there is none.
size_t tokenBefore(const source::LexedText& lexed, size_t k) {
  while (k > 0) {
    --k;
    if (lexed[k].kind != source::TokenKind::Comment) return k;
  }
  return lexed.size();
}

// For the `:` at `colon` inside a function's parameter list: the token that ends the type of a
// parameter declared without a name (`float3 : NORMAL`, `in uint : SV_VertexID`,
// `vector<float, 4> : COLOR`), or lexed.size() when the parameter has a name.
size_t unnamedParameterType(const source::LexedText& lexed, size_t colon) {
  size_t typeEnd = tokenBefore(lexed, colon), typeBegin = typeEnd;
  if (typeEnd >= lexed.size()) return lexed.size();
  if (lexed.isPunct(typeEnd, '>')) {
    int depth = 0;
    for (size_t k = typeEnd;; k = tokenBefore(lexed, k)) {
      if (k >= lexed.size()) return lexed.size();
      if (lexed.isPunct(k, '>')) ++depth;
      if (lexed.isPunct(k, '<') && --depth == 0) {
        typeBegin = tokenBefore(lexed, k);
        break;
      }
    }
  }
  if (typeBegin >= lexed.size() || !lexed.isIdentifier(typeBegin)) return lexed.size();
  size_t before = tokenBefore(lexed, typeBegin);
  if (before >= lexed.size()) return lexed.size();
  bool opensParameter = lexed.isPunct(before, '(') || lexed.isPunct(before, ',') ||
                        (lexed.isIdentifier(before) && isParameterModifier(lexed.text(before)));
  return opensParameter ? typeEnd : lexed.size();
}

std::string upperCase(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

}  // namespace

std::string liftHlslIdioms(const std::string& text, std::string* what) {
  if (what) what->clear();
  bool mayHaveCmp = text.find("cmp") != std::string::npos;
  bool mayHaveIndexedSystemValue = text.find("SV_") != std::string::npos || text.find("sv_") != std::string::npos;
  bool mayHaveMatrixSwizzle = text.find("._") != std::string::npos;
  bool maySemantics = text.find(':') != std::string::npos;
  if (!mayHaveCmp && !mayHaveIndexedSystemValue && !mayHaveMatrixSwizzle && !maySemantics) return text;
  source::LexedText lexed(text);
  struct Edit {
    size_t begin, end;
    std::string with;
  };
  std::vector<Edit> edits;  // in text order: the loop below walks the tokens once
  std::string semantic, matrixSwizzle;
  bool cmp = false;
  std::map<std::string, std::string, std::less<>> matrixScalars;
  bool matricesRead = false;
  int braceDepth = 0, parenDepth = 0;  // of the program text
  size_t unnamedParameters = 0;
  for (size_t k = 0; k < lexed.size(); ++k) {
    if (lexed[k].isCode() && lexed[k].kind == source::TokenKind::Punctuation) {
      char c = lexed.text(k)[0];
      braceDepth += c == '{' ? 1 : c == '}' ? -1 : 0;
      parenDepth += c == '(' ? 1 : c == ')' ? -1 : 0;
    }
    // `M._m00_m10_m20_m30` read -> `float4(M._m00, M._m10, M._m20, M._m30)`: glslang's HLSL front end
    // gives a swizzle of several matrix components a constant 0 of the wrong type, which makes
    // invalid SPIR-V (and crashes it or the optimizer when the value is a call's argument); single
    // components it reads right. The receiver is repeated, so it must be a chain of names, members
    // and indices (no call, no side effect); a swizzle written to is left alone.
    if (mayHaveMatrixSwizzle && lexed.isIdentifier(k) && lexed[k].isCode() && k > 0 && lexed.isPunct(k - 1, '.')) {
      std::vector<std::string> parts = matrixSwizzleComponents(lexed.text(k));
      if (parts.empty()) continue;
      size_t nameToken = k - 1;
      size_t begin = receiverBegin(lexed, k - 1, &nameToken);
      if (begin == k - 1 || startsAssignment(lexed, lexed.nextNonComment(k))) continue;
      if (!edits.empty() && edits.back().end > lexed[begin].begin) continue;  // inside an earlier edit's text
      std::string_view receiver = lexed.text().substr(lexed[begin].begin, lexed[k - 1].begin - lexed[begin].begin);
      if (receiver.find("++") != std::string_view::npos || receiver.find("--") != std::string_view::npos ||
          receiver.find('\n') != std::string_view::npos)
        continue;
      if (!matricesRead) {
        matrixScalars = matrixDeclarations(lexed);
        matricesRead = true;
      }
      auto scalar = matrixScalars.find(lexed.text(nameToken));
      std::string with = (scalar == matrixScalars.end() ? std::string("float") : scalar->second) +
                         std::to_string(parts.size()) + "(";
      for (size_t p = 0; p < parts.size(); ++p) with += (p ? ", " : "") + std::string(receiver) + "." + parts[p];
      edits.push_back({lexed[begin].begin, lexed[k].end, with + ")"});
      if (matrixSwizzle.empty()) matrixSwizzle = std::string(receiver) + "." + std::string(lexed.text(k));
      continue;
    }
    // `float3 : NORMAL` in a function's parameter list -> `float3 stereoshift_unnamed0 : NORMAL`:
    // HLSL lets a parameter go unnamed (an input the entry point does not read, kept for its place
    // in the signature) and glslang's HLSL parser crashes on it. Outside every brace (not a struct
    // member or packoffset), inside parentheses (not the return semantic or a register binding).
    if (lexed.isPunct(k, ':') && lexed[k].isCode() && braceDepth == 0 && parenDepth > 0) {
      size_t typeEnd = unnamedParameterType(lexed, k);
      if (typeEnd < lexed.size())
        edits.push_back({lexed[typeEnd].end, lexed[typeEnd].end,
                         " stereoshift_unnamed" + std::to_string(unnamedParameters++)});
    }
    // `: SV_POSITION0` -> `: SV_POSITION ` (the same columns after it).
    if (lexed.isPunct(k, ':') && !lexed[k].inDirective()) {
      size_t name = lexed.nextNonComment(k);
      if (!lexed.isIdentifier(name)) continue;
      std::string_view spelled = lexed.text(name);
      if (spelled.size() < 2 || spelled.back() != '0' ||
          !isUnindexedSystemValue(upperCase(spelled.substr(0, spelled.size() - 1))))
        continue;
      edits.push_back({lexed[name].end - 1, lexed[name].end, " "});
      if (semantic.empty()) semantic = std::string(spelled);
      continue;
    }
    // `#define cmp -`: the name, then exactly one token, a minus, on the line.
    if (lexed[k].kind != source::TokenKind::Directive || lexed[k].directive != source::DirectiveKind::Define) continue;
    size_t name = lexed.firstOperand(k), end = lexed.directiveLineEnd(k);
    if (name >= end || lexed.text(name) != "cmp") continue;
    size_t body = lexed.nextNonComment(name);
    if (body >= end || !lexed.isPunct(body, '-') || lexed.nextNonComment(body) < end) continue;
    if (lexed[body].begin == lexed[name].end) continue;  // `#define cmp-`: not the idiom's spelling
    edits.push_back({lexed[name].begin, lexed[body].end, "cmp(x) (0 - (x))"});
    cmp = true;
  }
  if (edits.empty()) return text;
  std::string out;
  size_t copied = 0;
  for (const Edit& e : edits) {
    out.append(text, copied, e.begin - copied);
    out += e.with;
    copied = e.end;
  }
  out.append(text, copied, std::string::npos);
  if (what) {
    if (!semantic.empty()) *what = "system-value semantics with index 0 (" + semantic + ") read without it";
    if (cmp) *what += std::string(what->empty() ? "" : "; ") + "the decompiler's `#define cmp -` read as `#define cmp(x) (0 - (x))`";
    if (!matrixSwizzle.empty())
      *what += std::string(what->empty() ? "" : "; ") + "swizzles of several matrix components (" + matrixSwizzle +
               ") read one component at a time";
    if (unnamedParameters)
      *what += std::string(what->empty() ? "" : "; ") + std::to_string(unnamedParameters) +
               " parameter(s) declared without a name given one";
  }
  return out;
}

std::string hlslForGlslang(const std::string& text, std::string* what) {
  return liftHlslIdioms(blankEffectBlocks(text), what);
}

}  // namespace stereoshift
