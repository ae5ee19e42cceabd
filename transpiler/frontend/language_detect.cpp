// Language detection by file name and by content: this turns a shader's text into "GLSL" or "HLSL"
// by weighing the constructs only one of the two languages has. See language_detect.h for the order
// of the rules; this file holds the scorer, which reads the lexer's tokens.
#include "transpiler/frontend/language_detect.h"

#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>
#include <unordered_set>

namespace stereoshift {

namespace {

enum class TokenKind { Identifier, Number, Punct, Directive };

struct Token {
  TokenKind kind;
  std::string text;  // Directive: the directive's name (`version`, `define`, ...)
};

// The lexer's tokens as the scorer reads them: comments are dropped, so a commented-out HLSL line in
// a GLSL file is no evidence; a string literal's text is no evidence either, but an include's file
// name is, so a literal is kept whole as punctuation. A directive is its name (`version`,
// `define`, ...), then the rest of its line; `#define NAME` adds NAME to `macros` instead: a GLSL
// file that maps `float4` to `vec4` with a macro is not HLSL for it. `::` is one token.
// `stopAtVersion`: stop at a `#version` directive (the decision is then made; most GLSL files start
// with one).
std::vector<Token> tokenize(const std::string& text, std::set<std::string>* macros, bool stopAtVersion = false) {
  std::vector<Token> tokens;
  source::Lexer lexer(text);
  source::Token t;
  std::string scratch;
  bool directiveName = false, macroName = false;  // the next token names the directive / the macro
  size_t colonEnd = std::string::npos;             // where the last lone `:` token ends
  while (lexer.next(t)) {
    if (t.kind == source::TokenKind::Comment) continue;
    if (t.kind == source::TokenKind::Directive) {
      if (directiveName) tokens.push_back({TokenKind::Directive, ""});  // the one before had no name
      directiveName = true;
      macroName = false;
      continue;
    }
    std::string_view spelled = source::spelling(text, t, scratch);
    bool nameLike = t.kind == source::TokenKind::Identifier || t.kind == source::TokenKind::Number;
    if (directiveName) {
      directiveName = false;
      bool named = t.inDirective() && nameLike;
      tokens.push_back({TokenKind::Directive, named ? std::string(spelled) : ""});
      if (stopAtVersion && tokens.back().text == "version") break;
      macroName = tokens.back().text == "define";
      if (named) continue;
    }
    if (macroName) {
      macroName = false;
      if (t.inDirective() && nameLike) {
        macros->insert(std::string(spelled));
        continue;
      }
    }
    switch (t.kind) {
      case source::TokenKind::Identifier: tokens.push_back({TokenKind::Identifier, std::string(spelled)}); break;
      case source::TokenKind::Number: tokens.push_back({TokenKind::Number, std::string(spelled)}); break;
      case source::TokenKind::String: tokens.push_back({TokenKind::Punct, std::string(source::tokenText(text, t))}); break;
      default:
        if (text[t.begin] == ':' && colonEnd == t.begin) {
          tokens.back().text = "::";
          colonEnd = std::string::npos;
          continue;
        }
        tokens.push_back({TokenKind::Punct, std::string(1, text[t.begin])});
        colonEnd = text[t.begin] == ':' ? t.end : std::string::npos;
        continue;
    }
    colonEnd = std::string::npos;
  }
  if (directiveName) tokens.push_back({TokenKind::Directive, ""});
  return tokens;
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// HLSL's numeric vector and matrix types: float4, half3, int2, uint4x4, min16float3, ...
bool isHlslVectorType(const std::string& word) {
  static const char* const scalars[] = {"min16float", "min10float", "min16int", "min12int", "min16uint",
                                        "double", "float", "half", "uint", "int", "bool", "dword"};
  for (const char* scalar : scalars) {
    if (!startsWith(word, scalar)) continue;
    std::string_view rest = std::string_view(word).substr(std::char_traits<char>::length(scalar));
    auto dim = [](char d) { return d >= '1' && d <= '4'; };
    if (rest.size() == 1 && dim(rest[0])) return true;
    if (rest.size() == 3 && dim(rest[0]) && rest[1] == 'x' && dim(rest[2])) return true;
    return false;
  }
  return false;
}

// GLSL's vector and matrix types: vec3, ivec2, uvec4, bvec2, dvec3, mat4, mat3x4, dmat2.
bool isGlslVectorType(const std::string& word) {
  std::string w = word;
  if (w.size() > 1 && (w[0] == 'i' || w[0] == 'u' || w[0] == 'b' || w[0] == 'd') && (startsWith(w.substr(1), "vec") || startsWith(w.substr(1), "mat")))
    w = w.substr(1);
  auto dim = [](char d) { return d >= '2' && d <= '4'; };
  if (w.size() == 4 && startsWith(w, "vec") && dim(w[3])) return true;
  if (w.size() == 4 && startsWith(w, "mat") && dim(w[3])) return true;
  if (w.size() == 6 && startsWith(w, "mat") && dim(w[3]) && w[4] == 'x' && dim(w[5])) return true;
  return false;
}

// D3D9-style semantics that HLSL still accepts (with an optional index: TEXCOORD0, COLOR1).
bool isLegacySemantic(const std::string& word) {
  static const std::unordered_set<std::string> names = {
      "POSITION", "POSITIONT", "NORMAL", "TEXCOORD", "COLOR", "TANGENT", "BINORMAL", "BLENDWEIGHT",
      "BLENDINDICES", "PSIZE", "FOG", "DEPTH", "VPOS", "VFACE", "TESSFACTOR"};
  std::string upper = word;
  while (!upper.empty() && std::isdigit(static_cast<unsigned char>(upper.back()))) upper.pop_back();
  std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
  return names.count(upper) > 0;
}

const std::unordered_set<std::string>& hlslObjectTypes() {
  static const std::unordered_set<std::string> names = {
      "Texture1D", "Texture1DArray", "Texture2D", "Texture2DArray", "Texture2DMS", "Texture2DMSArray",
      "Texture3D", "TextureCube", "TextureCubeArray", "RWTexture1D", "RWTexture1DArray", "RWTexture2D",
      "RWTexture2DArray", "RWTexture3D", "SamplerState", "SamplerComparisonState", "StructuredBuffer",
      "RWStructuredBuffer", "ByteAddressBuffer", "RWByteAddressBuffer", "AppendStructuredBuffer",
      "ConsumeStructuredBuffer", "ConstantBuffer", "RWBuffer", "InputPatch", "OutputPatch",
      "TriangleStream", "LineStream", "PointStream"};
  return names;
}

// Keywords of one language that the other does not have (and does not reserve for use).
const std::unordered_set<std::string>& hlslKeywords() {
  static const std::unordered_set<std::string> names = {"cbuffer", "tbuffer", "groupshared", "nointerpolation",
                                                        "technique", "technique10", "technique11", "static"};
  return names;
}

// Intrinsics only HLSL has; weak, since a GLSL shader may define a helper of the same name (such
// definitions are excluded before they count).
const std::unordered_set<std::string>& hlslIntrinsics() {
  static const std::unordered_set<std::string> names = {
      "mul", "saturate", "lerp", "frac", "rsqrt", "ddx", "ddy", "ddx_fine", "ddy_fine", "atan2", "fmod",
      "clip", "tex2D", "tex2Dlod", "tex2Dproj", "texCUBE", "asfloat", "asuint", "asint", "countbits",
      "firstbithigh", "firstbitlow", "sincos", "rcp", "mad", "f32tof16", "f16tof32", "InterlockedAdd",
      "GroupMemoryBarrierWithGroupSync", "DeviceMemoryBarrier", "AllMemoryBarrierWithGroupSync"};
  return names;
}

// Methods of HLSL's texture and stream objects: `.Sample(`, `.Load(`, `.Append(`.
const std::unordered_set<std::string>& hlslMethods() {
  static const std::unordered_set<std::string> names = {
      "Sample", "SampleLevel", "SampleCmp", "SampleCmpLevelZero", "SampleGrad", "SampleBias", "Load",
      "Gather", "GatherRed", "GetDimensions", "Append", "RestartStrip", "CalculateLevelOfDetail"};
  return names;
}

// `[numthreads(8, 8, 1)]`, `[maxvertexcount(4)]`, `[unroll]`, ...: HLSL's bracketed attributes.
const std::unordered_set<std::string>& hlslAttributes() {
  static const std::unordered_set<std::string> names = {
      "numthreads", "maxvertexcount", "domain", "partitioning", "outputtopology", "outputcontrolpoints",
      "patchconstantfunc", "maxtessfactor", "earlydepthstencil", "unroll", "loop", "branch", "flatten",
      "fastopt", "allow_uav_condition", "instance", "forcecase", "call"};
  return names;
}

// Built-in functions only GLSL has; the texture lookups of GLSL 1.x are strong, the rest weak.
const std::unordered_set<std::string>& glslLegacyLookups() {
  static const std::unordered_set<std::string> names = {"texture2D", "texture2DProj", "texture2DLod", "textureCube",
                                                        "textureCubeLod", "shadow2D", "texture3D", "texture1D"};
  return names;
}
const std::unordered_set<std::string>& glslIntrinsics() {
  static const std::unordered_set<std::string> names = {"texture", "texelFetch", "textureLod", "textureSize",
                                                        "mix", "fract", "inversesqrt", "dFdx", "dFdy", "fwidth"};
  return names;
}

class Scorer {
 public:
  Scorer(const std::vector<Token>& tokens, const std::set<std::string>& macros) : tokens_(tokens), macros_(macros) {
    collectDefinedFunctions();
  }

  LanguageEvidence run() {
    int braces = 0, parens = 0, pendingTernaries = 0;
    for (size_t i = 0; i < tokens_.size(); ++i) {
      const Token& t = tokens_[i];
      if (t.kind == TokenKind::Directive) {
        directive(i);
        continue;
      }
      if (t.kind == TokenKind::Punct) {
        const std::string& p = t.text;
        if (p == "{") ++braces, pendingTernaries = 0;
        else if (p == "}") --braces, pendingTernaries = 0;
        else if (p == ";") pendingTernaries = 0;
        else if (p == "(") ++parens;
        else if (p == ")") --parens;
        else if (p == "?") ++pendingTernaries;
        else if (p == ":") {
          if (pendingTernaries > 0) --pendingTernaries;  // the `:` of `a ? b : c`
          else semantic(i);
        } else if (p == "[") bracket(i);
        continue;
      }
      if (t.kind != TokenKind::Identifier || macros_.count(t.text)) continue;
      identifier(i, braces == 0 && parens == 0);
    }
    return evidence_;
  }

 private:
  const Token* at(size_t i) const { return i < tokens_.size() ? &tokens_[i] : nullptr; }
  bool punctAt(size_t i, const char* text) const {
    const Token* t = at(i);
    return t && t->kind == TokenKind::Punct && t->text == text;
  }
  bool identifierAt(size_t i) const {
    const Token* t = at(i);
    return t && t->kind == TokenKind::Identifier;
  }

  void hlsl(const std::string& sign, int weight) { add(sign, weight, evidence_.hlslSigns, evidence_.hlslScore); }
  void glsl(const std::string& sign, int weight) { add(sign, weight, evidence_.glslSigns, evidence_.glslScore); }
  void add(const std::string& sign, int weight, std::vector<std::string>& signs, int& score) {
    if (!seen_.insert(sign).second) return;  // each distinct sign counts once
    signs.push_back(sign);
    score += weight;
  }

  // Functions the shader defines itself (`float saturate(float x) {` at file scope): a call to one of
  // them is no evidence of the language whose built-in has that name.
  void collectDefinedFunctions() {
    int braces = 0;
    for (size_t i = 0; i + 1 < tokens_.size(); ++i) {
      if (punctAt(i, "{")) ++braces;
      if (punctAt(i, "}")) --braces;
      if (braces == 0 && i > 0 && identifierAt(i - 1) && identifierAt(i) && punctAt(i + 1, "("))
        defined_.insert(tokens_[i].text);
    }
  }

  void directive(size_t i) {
    const std::string& name = tokens_[i].text;
    if (name == "version") evidence_.hasVersion = true;
    else if (name == "extension") glsl("#extension", 3);
    else if (name == "pragma" && identifierAt(i + 1)) {
      const std::string& what = tokens_[i + 1].text;
      if (what == "pack_matrix") hlsl("#pragma pack_matrix", 3);
      if (what == "shader_stage") glsl("#pragma shader_stage", 3);
    } else if (name == "include" && at(i + 1)) {
      std::string file = tokens_[i + 1].text;
      std::transform(file.begin(), file.end(), file.begin(), ::tolower);
      for (const char* ext : {".hlsli\"", ".hlsl\"", ".fxh\"", ".fx\""})
        if (file.ends_with(ext)) hlsl("#include of an HLSL file", 3);
      if (file.ends_with(".glsl\"")) glsl("#include of a GLSL file", 3);
    }
  }

  // `: SV_Position`, `: TEXCOORD0`, `: register(b0)` after a parameter, member or function: HLSL
  // semantics. `case X:` labels and the `:` of a ternary are not.
  void semantic(size_t i) {
    if (i == 0 || !identifierAt(i + 1)) return;
    const Token& before = tokens_[i - 1];
    bool afterDeclarator = before.kind == TokenKind::Identifier || (before.kind == TokenKind::Punct && (before.text == ")" || before.text == "]"));
    if (!afterDeclarator || before.text == "default" || (i >= 2 && tokens_[i - 2].text == "case")) return;
    const std::string& name = tokens_[i + 1].text;
    const Token* after = at(i + 2);
    bool endsDeclarator = !after || (after->kind == TokenKind::Punct &&
                                     (after->text == ";" || after->text == "," || after->text == ")" || after->text == "{"));
    if (!endsDeclarator) return;  // `: register(` and `: packoffset(` count as calls
    std::string upper = name;
    std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
    if (startsWith(upper, "SV_")) hlsl(": " + name, 3);
    else if (isLegacySemantic(name)) hlsl(": " + name, 2);
  }

  // `[numthreads(...)]`, `[unroll]` and `[[vk::binding(0, 0)]]` where a declaration or statement
  // starts (after `;`, `{`, `}`, `)` of an `if` never precedes one, an index follows a name).
  void bracket(size_t i) {
    if (i > 0) {
      const Token& before = tokens_[i - 1];
      if (before.kind == TokenKind::Identifier || before.kind == TokenKind::Number || before.text == "]" ||
          before.text == ")")
        return;  // indexing
    }
    if (punctAt(i + 1, "[") && identifierAt(i + 2) && punctAt(i + 3, "::") && identifierAt(i + 4)) {
      hlsl("[[" + tokens_[i + 2].text + "::" + tokens_[i + 4].text + "]]", 3);
      return;
    }
    if (identifierAt(i + 1) && hlslAttributes().count(tokens_[i + 1].text) && (punctAt(i + 2, "(") || punctAt(i + 2, "]")))
      hlsl("[" + tokens_[i + 1].text + "]", 3);
  }

  void identifier(size_t i, bool fileScope) {
    const std::string& w = tokens_[i].text;
    bool call = punctAt(i + 1, "(");
    bool method = i > 0 && punctAt(i - 1, ".");
    bool builtinCall = call && !method && !defined_.count(w);
    // HLSL
    if (isHlslVectorType(w)) hlsl(w, 2);
    else if (hlslObjectTypes().count(w) || ((w == "Buffer" || w == "matrix" || w == "vector") && punctAt(i + 1, "<")))
      hlsl(w, 3);
    else if (hlslKeywords().count(w)) hlsl(w, w == "static" ? 2 : 3);
    else if ((w == "register" || w == "packoffset") && call && i > 0 && punctAt(i - 1, ":")) hlsl(": " + w + "(", 3);
    else if (builtinCall && hlslIntrinsics().count(w)) hlsl(w + "(", 1);
    else if (method && call && hlslMethods().count(w)) hlsl("." + w + "(", 2);
    // GLSL
    else if (startsWith(w, "gl_") && w.size() > 3) glsl(w, 3);
    else if (w == "attribute" || w == "varying") glsl(w, 3);
    else if (w == "precision" && identifierAt(i + 1) &&
             (tokens_[i + 1].text == "highp" || tokens_[i + 1].text == "mediump" || tokens_[i + 1].text == "lowp"))
      glsl("precision", 3);
    else if (w == "highp" || w == "mediump" || w == "lowp") glsl(w, 2);
    else if (w == "layout" && call) glsl("layout(", 3);
    else if (isGlslVectorType(w)) glsl(w, 2);
    else if (startsWith(w, "sampler") && w.size() > 7 && std::isdigit(static_cast<unsigned char>(w[7]))) glsl(w, 1);  // D3D9 HLSL has sampler2D too
    else if (w == "samplerCube" || startsWith(w, "isampler") || startsWith(w, "usampler") || startsWith(w, "image2D") ||
             (startsWith(w, "sampler") && w.ends_with("Shadow")))
      glsl(w, 2);
    else if (builtinCall && glslLegacyLookups().count(w)) glsl(w + "(", 2);
    else if (builtinCall && glslIntrinsics().count(w)) glsl(w + "(", 1);
    // `in vec3 position;` / `out vec4 color;` at file scope: GLSL >= 130 (HLSL's in/out qualify parameters)
    else if ((w == "in" || w == "out") && fileScope && identifierAt(i + 1) && identifierAt(i + 2))
      glsl("global " + w, 2);
  }

  const std::vector<Token>& tokens_;
  const std::set<std::string>& macros_;
  std::set<std::string> defined_;
  std::set<std::string> seen_;
  LanguageEvidence evidence_;
};

std::string joinSigns(const std::vector<std::string>& signs, size_t most) {
  std::string text;
  for (size_t k = 0; k < signs.size() && k < most; ++k) text += (k ? ", " : "") + signs[k];
  if (signs.size() > most) text += ", ...";
  return text;
}

}  // namespace

std::optional<SourceLanguage> languageFromFileName(const std::string& path) {
  std::string lower = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  for (const char* ext : {".hlsl", ".hlsli", ".fx", ".fxh"})
    if (lower.ends_with(ext)) return SourceLanguage::Hlsl;
  if (lower.ends_with(".glsl")) return SourceLanguage::Glsl;
  return std::nullopt;
}

LanguageEvidence scoreLanguage(const std::string& text) {
  std::set<std::string> macros;
  std::vector<Token> tokens = tokenize(text, &macros);
  return Scorer(tokens, macros).run();
}

LanguageDecision decideLanguage(const std::string& path, const std::string& text, std::optional<SourceLanguage> flag) {
  LanguageDecision d;
  if (flag) {
    d.language = *flag;
    d.source = LanguageSource::Flag;
    d.reason = *flag == SourceLanguage::Hlsl ? "-x hlsl" : "-x glsl";
    return d;
  }
  if (auto named = languageFromFileName(path)) {
    d.language = *named;
    d.source = LanguageSource::Extension;
    d.reason = "file extension " + path.substr(path.find_last_of('.'));
    return d;
  }
  if (stageOfDecompiledDump(path)) {
    d.language = SourceLanguage::Hlsl;
    d.source = LanguageSource::Extension;
    d.reason = "3Dmigoto dump name (*_replace.txt: decompiled HLSL)";
    return d;
  }
  d.source = LanguageSource::Content;
  std::set<std::string> macros;
  std::vector<Token> head = tokenize(text, &macros, true);
  bool hasVersion = !head.empty() && head.back().kind == TokenKind::Directive && head.back().text == "version";
  LanguageEvidence e = hasVersion ? LanguageEvidence{} : Scorer(head, macros).run();  // no #version: `head` is all
  if (hasVersion) {
    d.language = SourceLanguage::Glsl;
    d.reason = "#version directive";
    return d;
  }
  std::string scores = " (HLSL " + std::to_string(e.hlslScore) + ", GLSL " + std::to_string(e.glslScore) + ")";
  if (e.hlslScore >= kHlslScoreThreshold && e.hlslScore > e.glslScore) {
    d.language = SourceLanguage::Hlsl;
    d.reason = "no #version; HLSL constructs: " + joinSigns(e.hlslSigns, 4) + scores;
  } else {
    d.language = SourceLanguage::Glsl;
    d.reason = e.glslSigns.empty() ? "no #version and no HLSL constructs: GLSL by default" + scores
                                   : "no #version; GLSL constructs: " + joinSigns(e.glslSigns, 4) + scores;
  }
  return d;
}

const char* languageSourceName(LanguageSource source) {
  switch (source) {
    case LanguageSource::Extension: return "extension";
    case LanguageSource::Flag: return "flag";
    case LanguageSource::Content: return "content";
  }
  return "?";
}

}  // namespace stereoshift
