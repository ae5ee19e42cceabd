// This turns HLSL effect-file text into what glslang can parse, and reads which entry points its
// techniques compile and which one to compile (see hlsl_effects.h). It reads the lexer's tokens
// outside comments, strings and directives; nothing here needs more of HLSL.
#include "transpiler/frontend/hlsl_effects.h"

#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <cctype>
#include <optional>
#include <set>
#include <string_view>

namespace stereoshift {

namespace {

struct Word {
  size_t begin, end;
  bool identifier;
};

// The identifiers, numbers and punctuation of `text` outside comments, strings and preprocessor
// lines, in order, as the lexer reads them.
std::vector<Word> words(const std::string& text) {
  std::vector<Word> out;
  source::Lexer lexer(text);
  source::Token t;
  while (lexer.next(t)) {
    if (!t.isCode() || t.kind == source::TokenKind::String) continue;
    out.push_back({t.begin, t.end, t.kind == source::TokenKind::Identifier});
  }
  return out;
}

std::string lowered(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

class EffectText {
 public:
  explicit EffectText(const std::string& text) : text_(text), words_(words(text)) {}

  std::string_view at(size_t k) const {
    return k < words_.size() ? std::string_view(text_).substr(words_[k].begin, words_[k].end - words_[k].begin)
                             : std::string_view();
  }
  bool is(size_t k, char c) const { return at(k).size() == 1 && at(k)[0] == c; }
  bool isIdent(size_t k) const { return k < words_.size() && words_[k].identifier; }
  size_t size() const { return words_.size(); }
  const Word& word(size_t k) const { return words_[k]; }

  // The word that closes the bracket opened at `k`, or npos.
  size_t closing(size_t k) const {
    char open = at(k)[0], close = open == '{' ? '}' : open == '(' ? ')' : ']';
    int depth = 0;
    for (size_t j = k; j < words_.size(); ++j) {
      if (is(j, open)) ++depth;
      if (is(j, close) && --depth == 0) return j;
    }
    return std::string::npos;
  }

 private:
  const std::string& text_;
  std::vector<Word> words_;
};

}  // namespace

std::string blankEffectBlocks(const std::string& text) {
  static const std::set<std::string> techniques = {"technique", "technique10", "technique11"};
  static const std::set<std::string> stateObjects = {"blendstate", "depthstencilstate", "rasterizerstate"};
  static const std::set<std::string> shaderObjects = {"vertexshader", "pixelshader", "geometryshader",
                                                      "hullshader", "domainshader", "computeshader"};
  EffectText e(text);
  std::string out;
  std::vector<std::pair<size_t, size_t>> spans;  // byte ranges to blank
  int depth = 0;
  for (size_t k = 0; k < e.size(); ++k) {
    if (e.is(k, '{')) ++depth;
    if (e.is(k, '}')) --depth;
    if (depth != 0 || !e.isIdent(k)) continue;
    std::string w = lowered(e.at(k));
    // `technique11 Name <annotations> { ... }`, `BlendState Name { ... };`
    if (techniques.count(w) || (stateObjects.count(w) && e.isIdent(k + 1))) {
      size_t open = k + 1;
      while (open < e.size() && !e.is(open, '{') && !e.is(open, ';')) ++open;
      if (open >= e.size() || !e.is(open, '{')) continue;
      size_t close = e.closing(open);
      if (close == std::string::npos) continue;
      if (e.is(close + 1, ';')) ++close;
      spans.push_back({e.word(k).begin, e.word(close).end});
      k = close;
      continue;
    }
    // `VertexShader vsObject = CompileShader(vs_5_0, VS());`
    if (shaderObjects.count(w) && e.isIdent(k + 1) && e.is(k + 2, '=')) {
      size_t end = k + 3;
      while (end < e.size() && !e.is(end, ';')) ++end;
      if (end >= e.size()) continue;
      spans.push_back({e.word(k).begin, e.word(end).end});
      k = end;
    }
  }
  if (spans.empty()) return text;
  out = text;
  for (auto [begin, end] : spans) {
    for (size_t i = begin; i < end; ++i) {
      if (out[i] != '\n' && out[i] != '\r') out[i] = ' ';
    }
  }
  return out;
}

namespace {

std::vector<std::pair<Stage, std::string>> techniqueEntryPoints(const EffectText& e) {
  std::vector<std::pair<Stage, std::string>> found;
  auto add = [&](std::string_view profile, std::string_view name) {
    Stage stage = stageFromHlslProfile(profile);
    if (stage == Stage::Unknown) return;
    for (const auto& f : found) {
      if (f.second == name) return;
    }
    found.push_back({stage, std::string(name)});
  };
  for (size_t k = 0; k + 3 < e.size(); ++k) {
    if (e.at(k) == "CompileShader" && e.is(k + 1, '(') && e.isIdent(k + 2) && e.is(k + 3, ',') && e.isIdent(k + 4) &&
        e.is(k + 5, '(')) {
      add(e.at(k + 2), e.at(k + 4));
    } else if (lowered(e.at(k)) == "compile" && e.isIdent(k + 1) && e.isIdent(k + 2) && e.is(k + 3, '(')) {
      add(e.at(k + 1), e.at(k + 2));
    }
  }
  return found;
}

std::string entryPointBySignature(const EffectText& e, Stage stage) {
  if (stage != Stage::Vertex && stage != Stage::Fragment) return {};
  const std::string systemValue = stage == Stage::Vertex ? "sv_position" : "sv_target";
  auto isSystemValue = [&](size_t k) { return lowered(e.at(k)).starts_with(systemValue); };  // SV_Target1, SV_POSITION0
  // Structs with a member of that semantic.
  std::set<std::string> carriers;
  for (size_t k = 0; k + 2 < e.size(); ++k) {
    if (e.at(k) != "struct" || !e.isIdent(k + 1) || !e.is(k + 2, '{')) continue;
    size_t close = e.closing(k + 2);
    for (size_t j = k + 3; j < close && close != std::string::npos; ++j) {
      if (e.is(j, ':') && isSystemValue(j + 1)) carriers.insert(std::string(e.at(k + 1)));
    }
  }
  // Function definitions at file scope: `Type Name ( params ) [: SEMANTIC] {`.
  std::vector<std::string> candidates;
  std::set<std::string> called;
  int depth = 0;
  for (size_t k = 0; k < e.size(); ++k) {
    if (e.is(k, '{')) ++depth;
    if (e.is(k, '}')) --depth;
    if (depth > 0 && e.isIdent(k) && e.is(k + 1, '(')) called.insert(std::string(e.at(k)));
    if (depth != 0 || !e.isIdent(k) || !e.isIdent(k + 1) || !e.is(k + 2, '(')) continue;
    size_t close = e.closing(k + 2);
    if (close == std::string::npos) continue;
    bool returnsValue = e.is(close + 1, ':') && isSystemValue(close + 2) && e.is(close + 3, '{');
    bool body = e.is(close + 1, '{') || returnsValue;
    if (!body) continue;
    bool marked = returnsValue || carriers.count(std::string(e.at(k)));
    for (size_t j = k + 3; j < close && !marked; ++j) {
      if (e.at(j) != "out" && e.at(j) != "inout") continue;
      for (size_t t = j + 1; t < close && !e.is(t, ','); ++t) {
        if ((e.is(t, ':') && isSystemValue(t + 1)) || carriers.count(std::string(e.at(t)))) marked = true;
      }
    }
    if (marked) candidates.push_back(std::string(e.at(k + 1)));
    k = close;
  }
  for (const auto& name : candidates) {
    if (!called.count(name)) return name;
  }
  return {};
}

}  // namespace

std::vector<std::pair<Stage, std::string>> techniqueEntryPoints(const std::string& text) {
  return techniqueEntryPoints(EffectText(text));
}

std::string entryPointBySignature(const std::string& text, Stage stage) {
  return entryPointBySignature(EffectText(text), stage);
}

std::set<std::string> mentionedFunctions(const std::string& text) {
  std::set<std::string> names;
  source::Lexer lexer(text);
  source::Token t, before;  // `before`: the token ahead of `t`, comments left out
  bool any = false;
  while (lexer.next(t)) {
    if (t.kind == source::TokenKind::Comment) continue;
    if (any && before.kind == source::TokenKind::Identifier && t.kind == source::TokenKind::Punctuation &&
        text[t.begin] == '(')
      names.insert(source::spelledString(text, before));
    before = t;
    any = true;
  }
  return names;
}

const char* conventionalHlslEntry(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return "VSMain";
    case Stage::Fragment: return "PSMain";
    case Stage::Geometry: return "GSMain";
    case Stage::TessControl: return "HSMain";
    case Stage::TessEvaluation: return "DSMain";
    case Stage::Compute: return "CSMain";
    case Stage::Mesh: return "MSMain";
    case Stage::Task: return "ASMain";
    default: return nullptr;
  }
}

std::string chooseHlslEntry(const std::string& text, const std::set<std::string>& functions, Stage stage,
                            const std::string& requested) {
  if (!requested.empty()) return requested;
  if (functions.count("main")) return "main";
  const char* conventional = conventionalHlslEntry(stage);
  if (conventional && functions.count(conventional)) return conventional;
  EffectText e(text);
  // Effect files name their entry points in their techniques: the first one of this stage.
  for (const auto& [techniqueStage, name] : techniqueEntryPoints(e)) {
    if (techniqueStage == stage && functions.count(name)) return name;
  }
  // Else the signature says it (`VS`, `mainVS`, `RenderSceneVS`...): the first function of the file
  // whose outputs carry this stage's system value.
  if (std::string bySignature = entryPointBySignature(e, stage); !bySignature.empty()) return bySignature;
  return "main";
}

}  // namespace stereoshift
