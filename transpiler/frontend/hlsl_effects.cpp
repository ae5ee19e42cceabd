// This turns HLSL effect-file text into what glslang can parse, and reads which entry points its
// techniques compile (see hlsl_effects.h). A small scanner of its own: identifiers, brackets,
// comments and strings; nothing here needs more of HLSL.
#include "transpiler/frontend/hlsl_effects.h"

#include "passes/source_text.h"

#include <cctype>
#include <optional>
#include <set>
#include <string_view>

namespace stereoshift {

namespace {

struct Word {
  size_t begin, end;
};

// The identifiers and single-character punctuation of `text` outside comments, strings and
// preprocessor lines, in order.
std::vector<Word> words(const std::string& text) {
  std::vector<Word> out;
  bool lineStart = true;
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '\n') {
      lineStart = true;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#' && lineStart) {  // a directive: to the end of the line, line splices included
      while (i < text.size() && text[i] != '\n') i += text[i] == '\\' && i + 1 < text.size() ? 2 : 1;
      continue;
    }
    lineStart = false;
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      size_t close = text.find("*/", i + 2);
      i = close == std::string::npos ? text.size() : close + 2;
      continue;
    }
    if (c == '"') {
      size_t j = i + 1;
      while (j < text.size() && text[j] != '"' && text[j] != '\n') j += text[j] == '\\' ? 2 : 1;
      i = std::min(j + 1, text.size());
      continue;
    }
    if (isIdentifierChar(c)) {
      size_t j = i;
      while (j < text.size() && isIdentifierChar(text[j])) ++j;
      out.push_back({i, j});
      i = j;
      continue;
    }
    out.push_back({i, i + 1});
    ++i;
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
  bool isIdent(size_t k) const {
    return k < words_.size() && isIdentifierChar(text_[words_[k].begin]) &&
           !std::isdigit(static_cast<unsigned char>(text_[words_[k].begin]));
  }
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

std::vector<std::pair<Stage, std::string>> techniqueEntryPoints(const std::string& text) {
  EffectText e(text);
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

std::string entryPointBySignature(const std::string& text, Stage stage) {
  if (stage != Stage::Vertex && stage != Stage::Fragment) return {};
  const std::string systemValue = stage == Stage::Vertex ? "sv_position" : "sv_target";
  EffectText e(text);
  auto isSystemValue = [&](size_t k) { return lowered(e.at(k)).starts_with(systemValue); };
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

}  // namespace stereoshift
