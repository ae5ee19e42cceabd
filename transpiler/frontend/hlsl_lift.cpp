// See hlsl_lift.h.
#include "transpiler/frontend/hlsl_lift.h"

#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/source/lexer.h"

#include <cctype>
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
  if (!mayHaveCmp && !mayHaveIndexedSystemValue) return text;
  source::LexedText lexed(text);
  struct Edit {
    size_t begin, end;
    std::string with;
  };
  std::vector<Edit> edits;  // in text order: the loop below walks the tokens once
  std::string semantic;
  bool cmp = false;
  for (size_t k = 0; k < lexed.size(); ++k) {
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
  }
  return out;
}

std::string hlslForGlslang(const std::string& text, std::string* what) {
  return liftHlslIdioms(blankEffectBlocks(text), what);
}

}  // namespace stereoshift
