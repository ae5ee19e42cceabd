// This turns ESSL 100 and desktop GLSL 110-150 into ESSL 310 / GLSL 330 for analysis: see legacy_glsl.h.
#include "transpiler/frontend/legacy_glsl.h"


#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace stereoshift {

namespace {

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// One identifier of the source with what surrounds it, enough for a token-level rewrite.
struct Token {
  size_t begin = 0, end = 0;
  std::string text;
  bool inDirective = false;   // inside a preprocessor line
  std::string directive;      // the directive's name when inDirective ("define", "if", ...)
  int conditionalDepth = 0;   // #if nesting around it
  bool underGlEs = false;     // inside `#ifdef GL_ES` / `#if defined(GL_ES)`
};

struct Directive {
  size_t begin = 0, end = 0;  // the whole line, without its newline
  std::string name;           // "version", "extension", ...
  std::string rest;           // text after the name
};

// The identifiers and directives of `text`, skipping comments and numbers.
struct Scan {
  std::vector<Token> identifiers;
  std::vector<Directive> directives;
  std::vector<size_t> codeLineStarts;  // start of each line holding code outside any #if (in order)
};

Scan scan(const std::string& text) {
  Scan out;
  int depth = 0;
  std::vector<bool> glEsStack;  // per open #if: whether it tests GL_ES
  size_t lineStart = 0;
  bool atLineStart = true;  // only blanks since the line began
  bool lineHasCode = false;
  size_t i = 0;
  auto underGlEs = [&] { return std::find(glEsStack.begin(), glEsStack.end(), true) != glEsStack.end(); };
  while (i < text.size()) {
    char c = text[i];
    if (c == '\n') {
      ++i;
      lineStart = i;
      atLineStart = true;
      lineHasCode = false;
      continue;
    }
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      size_t close = text.find("*/", i + 2);
      i = close == std::string::npos ? text.size() : close + 2;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    if (c == '#' && atLineStart) {
      // A directive: to the end of the line, with `\` continuations.
      Directive d;
      d.begin = i;
      size_t end = i;
      while (end < text.size() && text[end] != '\n') {
        if (text[end] == '\\' && end + 1 < text.size() && text[end + 1] == '\n') end += 2;
        else if (text[end] == '\\' && text.compare(end + 1, 2, "\r\n") == 0) end += 3;
        else ++end;
      }
      d.end = end;
      if (d.end > d.begin && text[d.end - 1] == '\r') --d.end;
      size_t k = i + 1;
      while (k < d.end && (text[k] == ' ' || text[k] == '\t')) ++k;
      size_t nameBegin = k;
      while (k < d.end && isIdentChar(text[k])) ++k;
      d.name = text.substr(nameBegin, k - nameBegin);
      d.rest = text.substr(k, d.end - k);
      bool testsGlEs = d.rest.find("GL_ES") != std::string::npos;
      if (d.name == "if" || d.name == "ifdef" || d.name == "ifndef") {
        ++depth;
        glEsStack.push_back(d.name != "ifndef" && testsGlEs);
      } else if (d.name == "endif") {
        depth = std::max(0, depth - 1);
        if (!glEsStack.empty()) glEsStack.pop_back();
      } else if (d.name == "else" || d.name == "elif") {
        if (!glEsStack.empty()) glEsStack.back() = false;
      }
      // Macro bodies are code: their identifiers are rewritten like any other.
      if (d.name == "define") {
        for (size_t j = k; j < d.end;) {
          if (text.compare(j, 2, "//") == 0) break;
          if (isIdentStart(text[j])) {
            size_t b = j;
            while (j < d.end && isIdentChar(text[j])) ++j;
            out.identifiers.push_back({b, j, text.substr(b, j - b), true, d.name, depth, underGlEs()});
          } else if (std::isdigit(static_cast<unsigned char>(text[j]))) {
            while (j < d.end && (isIdentChar(text[j]) || text[j] == '.')) ++j;
          } else {
            ++j;
          }
        }
      }
      out.directives.push_back(d);
      i = end;
      continue;
    }
    atLineStart = false;
    if (!lineHasCode && depth == 0) out.codeLineStarts.push_back(lineStart);
    lineHasCode = true;
    if (isIdentStart(c)) {
      size_t b = i;
      while (i < text.size() && isIdentChar(text[i])) ++i;
      out.identifiers.push_back({b, i, text.substr(b, i - b), false, "", depth, underGlEs()});
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
      while (i < text.size() && (isIdentChar(text[i]) || text[i] == '.' ||
                                 ((text[i] == '+' || text[i] == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E'))))
        ++i;
      continue;
    }
    ++i;
  }
  return out;
}

// Extensions whose features ESSL 300 has in core: the translation drops their #extension lines.
bool isCoreInEssl300(const std::string& extension) {
  return extension == "GL_OES_standard_derivatives" || extension == "GL_EXT_shader_texture_lod" ||
         extension == "GL_EXT_frag_depth" || extension == "GL_EXT_draw_buffers";
}

std::string extensionName(const std::string& rest) {
  size_t i = 0;
  while (i < rest.size() && !isIdentStart(rest[i])) ++i;
  size_t b = i;
  while (i < rest.size() && isIdentChar(rest[i])) ++i;
  return rest.substr(b, i - b);
}

// 1xx texture lookups and their ESSL 300 / GLSL 130 names.
const std::map<std::string, std::string>& textureRenames() {
  static const std::map<std::string, std::string> renames = [] {
    std::map<std::string, std::string> m;
    for (const char* dim : {"1D", "2D", "3D", "Cube", "2DRect"}) {
      std::string d = dim;
      m["texture" + d] = "texture";
      m["texture" + d + "Proj"] = "textureProj";
      m["texture" + d + "Lod"] = "textureLod";
      m["texture" + d + "ProjLod"] = "textureProjLod";
      // GL_EXT_shader_texture_lod (ESSL 100 fragment shaders).
      m["texture" + d + "LodEXT"] = "textureLod";
      m["texture" + d + "ProjLodEXT"] = "textureProjLod";
      m["texture" + d + "GradEXT"] = "textureGrad";
      m["texture" + d + "ProjGradEXT"] = "textureProjGrad";
      m["texture" + d + "GradARB"] = "textureGrad";
      m["texture" + d + "ProjGradARB"] = "textureProjGrad";
    }
    // GL_EXT_shadow_samplers (ESSL 100): these already return a float.
    m["shadow2DEXT"] = "texture";
    m["shadow2DProjEXT"] = "textureProj";
    return m;
  }();
  return renames;
}

// Desktop shadow lookups return a vec4 in 1xx and a float from `texture`: helpers keep the vec4.
struct ShadowHelper {
  const char* name;
  const char* sampler;
  const char* coord;
  const char* call;  // the 130 function
  bool lod;
};
const ShadowHelper kShadowHelpers[] = {
    {"shadow1D", "sampler1DShadow", "vec3", "texture", false},
    {"shadow1DProj", "sampler1DShadow", "vec4", "textureProj", false},
    {"shadow1DLod", "sampler1DShadow", "vec3", "textureLod", true},
    {"shadow1DProjLod", "sampler1DShadow", "vec4", "textureProjLod", true},
    {"shadow2D", "sampler2DShadow", "vec3", "texture", false},
    {"shadow2DProj", "sampler2DShadow", "vec4", "textureProj", false},
    {"shadow2DLod", "sampler2DShadow", "vec3", "textureLod", true},
    {"shadow2DProjLod", "sampler2DShadow", "vec4", "textureProjLod", true},
};

// A compatibility built-in the translation declares: `storage type stereoshift_<name>[array]`.
struct CompatBuiltin {
  std::string storage;  // "in", "out" or "uniform"
  std::string type;
  std::string declaredName;  // stereoshift_...
  std::string arraySize;     // "" for none
};

// The compatibility built-ins of desktop GLSL 1xx, as `stage` sees them.
std::map<std::string, CompatBuiltin> compatBuiltins(Stage stage) {
  std::map<std::string, CompatBuiltin> m;
  auto add = [&](const std::string& glName, const std::string& storage, const std::string& type,
                 const std::string& declared, const std::string& array = "") {
    m[glName] = {storage, type, "stereoshift_" + declared, array};
  };
  // Uniform state of the fixed-function transform, in every stage.
  for (const char* base : {"ModelViewMatrix", "ProjectionMatrix", "ModelViewProjectionMatrix", "TextureMatrix"}) {
    std::string b = base;
    std::string array = b == "TextureMatrix" ? "8" : "";
    for (const char* suffix : {"", "Inverse", "Transpose", "InverseTranspose"})
      add("gl_" + b + suffix, "uniform", "mat4", b + suffix, array);
  }
  add("gl_NormalMatrix", "uniform", "mat3", "NormalMatrix");
  add("gl_NormalScale", "uniform", "float", "NormalScale");
  bool fragment = stage == Stage::Fragment;
  if (stage == Stage::Vertex) {
    add("gl_Vertex", "in", "vec4", "Vertex");
    add("gl_Normal", "in", "vec3", "Normal");
    add("gl_Color", "in", "vec4", "Color");
    add("gl_SecondaryColor", "in", "vec4", "SecondaryColor");
    add("gl_FogCoord", "in", "float", "FogCoord");
    for (int k = 0; k < 8; ++k)
      add("gl_MultiTexCoord" + std::to_string(k), "in", "vec4", "MultiTexCoord" + std::to_string(k));
  }
  if (fragment) {
    // The fragment stage reads the interpolated colours under the vertex stage's output names.
    add("gl_Color", "in", "vec4", "FrontColor");
    add("gl_SecondaryColor", "in", "vec4", "FrontSecondaryColor");
    add("gl_TexCoord", "in", "vec4", "TexCoord", "8");
    add("gl_FogFragCoord", "in", "float", "FogFragCoord");
  } else {
    add("gl_FrontColor", "out", "vec4", "FrontColor");
    add("gl_BackColor", "out", "vec4", "BackColor");
    add("gl_FrontSecondaryColor", "out", "vec4", "FrontSecondaryColor");
    add("gl_BackSecondaryColor", "out", "vec4", "BackSecondaryColor");
    add("gl_TexCoord", "out", "vec4", "TexCoord", "8");
    add("gl_FogFragCoord", "out", "float", "FogFragCoord");
    add("gl_ClipVertex", "out", "vec4", "ClipVertex");
  }
  return m;
}

// Compatibility state a translation cannot stand in for with a plain declaration (structs of the
// fixed-function pipeline): refused by name.
bool isUntranslatedCompatBuiltin(const std::string& name) {
  static const std::set<std::string> names = {
      "gl_LightSource", "gl_LightModel", "gl_FrontLightModelProduct", "gl_BackLightModelProduct",
      "gl_FrontLightProduct", "gl_BackLightProduct", "gl_FrontMaterial", "gl_BackMaterial", "gl_Fog",
      "gl_Point", "gl_ClipPlane", "gl_TextureEnvColor", "gl_EyePlaneS", "gl_EyePlaneT", "gl_EyePlaneR",
      "gl_EyePlaneQ", "gl_ObjectPlaneS", "gl_ObjectPlaneT", "gl_ObjectPlaneR", "gl_ObjectPlaneQ",
      "gl_FrontColorIn", "gl_BackColorIn", "gl_TexCoordIn", "gl_FogFragCoordIn", "gl_SecondaryColorIn"};
  return names.count(name) > 0;
}

// Words a 1xx shader may use as names that are keywords (or, for `texture`, a built-in function
// the translation calls) in ESSL 310 / GLSL 330: renamed in the translation.
bool isNewKeyword(const std::string& word, bool es) {
  static const std::set<std::string> common = {"layout", "centroid", "flat", "smooth", "uint", "uvec2", "uvec3",
                                               "uvec4", "texture", "invariant", "sample", "patch"};
  static const std::set<std::string> essl310 = {"buffer", "shared", "coherent", "restrict", "readonly",
                                                "writeonly", "precise"};
  static const std::set<std::string> glsl330 = {"noperspective", "precision", "lowp", "mediump", "highp"};
  return common.count(word) || (es ? essl310.count(word) : glsl330.count(word));
}

// Whether `name` is a compatibility built-in of any stage, translated or not.
bool isCompatBuiltin(const std::string& name) {
  static const std::set<std::string> names = [] {
    std::set<std::string> all;
    for (Stage stage : {Stage::Vertex, Stage::Fragment})
      for (const auto& [glName, builtin] : compatBuiltins(stage)) all.insert(glName);
    return all;
  }();
  return names.count(name) > 0 || isUntranslatedCompatBuiltin(name);
}

}  // namespace

LegacyDialect decideLegacyDialect(const std::string& text, const VersionLine& version) {
  LegacyDialect d;
  if (version.begin != std::string::npos) {
    d.versionWritten = true;
    d.version = version.version;
    d.es = version.es;
    d.legacy = d.es ? d.version < 300 : d.version < 330;
    d.reason = "#version " + std::to_string(d.version) + (d.es && d.version != 100 ? " es" : "");
    return d;
  }
  // No #version: GLSL's default is 110, ESSL's 100; what the text uses decides between them.
  d.legacy = true;
  Scan s = scan(text);
  for (const auto& t : s.identifiers) {
    if (t.text == "ftransform" || isCompatBuiltin(t.text)) {
      d.version = 110;
      d.reason = "no #version; uses the desktop compatibility built-in " + t.text + ", so GLSL's default 110";
      return d;
    }
  }
  for (const auto& dir : s.directives) {
    if (dir.name == "extension") {
      std::string ext = extensionName(dir.rest);
      if (ext.starts_with("GL_OES_") || isCoreInEssl300(ext) || ext == "GL_EXT_shadow_samplers") {
        d.version = 100;
        d.es = true;
        d.reason = "no #version; enables the OpenGL ES extension " + ext + ", so ESSL 100 (WebGL1)";
        return d;
      }
    }
  }
  for (const auto& t : s.identifiers) {
    if (t.inDirective) continue;
    bool precision = t.text == "precision" || t.text == "lowp" || t.text == "mediump" || t.text == "highp";
    if (precision || t.text == "gl_FragDepthEXT" || t.text.ends_with("LodEXT") || t.text.ends_with("GradEXT")) {
      d.version = 100;
      d.es = true;
      d.reason = std::string("no #version; uses `") + t.text + "`" +
                 (t.underGlEs ? " (under #ifdef GL_ES: written for OpenGL ES)" : " (OpenGL ES only)") +
                 ", so ESSL 100 (WebGL1)";
      return d;
    }
  }
  d.version = 110;
  d.reason = "no #version and nothing ES-only, so GLSL's default 110";
  return d;
}

LegacyTranslation translateLegacyGlsl(const std::string& text, Stage stage, const LegacyDialect& dialect,
                                      const std::string& path) {
  LegacyTranslation result;
  Scan s = scan(text);
  bool es = dialect.es;
  bool fragment = stage == Stage::Fragment;
  bool oneXX = es || dialect.version < 130;  // still without in/out storage and `texture`
  auto compat = es ? std::map<std::string, CompatBuiltin>{} : compatBuiltins(stage);

  struct Edit {
    size_t begin, end;
    std::string replacement;
  };
  std::vector<Edit> edits;
  std::set<std::string> declare;  // compat built-ins (by gl_ name) used
  std::set<std::string> helpers;  // shadow helpers used
  bool fragColor = false, fragData = false;
  auto located = [&](size_t offset, const std::string& message) {
    int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
    size_t ls = text.rfind('\n', offset == 0 ? 0 : offset - 1);
    ls = (ls == std::string::npos || offset == 0) ? 0 : ls + 1;
    result.error = Diagnostic{Severity::Error, path, line, static_cast<int>(offset - ls) + 1, message};
    return result;
  };

  for (const auto& d : s.directives) {
    if (d.name == "version") {
      edits.push_back({d.begin, d.end, es ? "#version 310 es" : "#version 330"});
    } else if (d.name == "extension" && es && isCoreInEssl300(extensionName(d.rest))) {
      edits.push_back({d.begin, d.end, ""});  // core in ESSL 300: the line stays, empty
    }
  }
  const auto& textures = textureRenames();
  for (size_t k = 0; k < s.identifiers.size(); ++k) {
    const Token& t = s.identifiers[k];
    const std::string& w = t.text;
    auto rename = [&](std::string to) { edits.push_back({t.begin, t.end, std::move(to)}); };
    if (oneXX && w == "attribute") {
      if (stage != Stage::Vertex) return located(t.begin, "'attribute' is only allowed in a vertex shader");
      rename("in");
    } else if (oneXX && w == "varying") {
      rename(fragment ? "in" : "out");
    } else if (dialect.version >= 130 && !es && (w == "attribute" || w == "varying")) {
      rename(w == "attribute" ? "in" : (fragment ? "in" : "out"));  // deprecated in 130-150, still accepted
    } else if (auto tex = textures.find(w); tex != textures.end()) {
      rename(tex->second);
    } else if (!es && std::any_of(std::begin(kShadowHelpers), std::end(kShadowHelpers),
                                  [&](const ShadowHelper& h) { return w == h.name; })) {
      helpers.insert(w);
      rename("stereoshift_" + w);
    } else if (w == "gl_FragColor" && fragment) {
      fragColor = true;
      rename("stereoshift_FragColor");
    } else if (w == "gl_FragData" && fragment) {
      fragData = true;
      rename("stereoshift_FragData");
    } else if (w == "gl_FragDepthEXT") {
      rename("gl_FragDepth");
    } else if (!es && w == "ftransform") {
      // ftransform() -> (MVP * vertex): the call's `(` and `)` go with it.
      size_t open = t.end;
      while (open < text.size() && std::isspace(static_cast<unsigned char>(text[open]))) ++open;
      size_t close = open < text.size() && text[open] == '(' ? open + 1 : std::string::npos;
      while (close != std::string::npos && close < text.size() && std::isspace(static_cast<unsigned char>(text[close])))
        ++close;
      if (close == std::string::npos || close >= text.size() || text[close] != ')')
        return located(t.begin, "ftransform must be called as `ftransform()`");
      if (stage != Stage::Vertex) return located(t.begin, "ftransform() is only available in a vertex shader");
      declare.insert("gl_ModelViewProjectionMatrix");
      declare.insert("gl_Vertex");
      edits.push_back({t.begin, close + 1, "(stereoshift_ModelViewProjectionMatrix * stereoshift_Vertex)"});
    } else if (compat.count(w)) {
      declare.insert(w);
      rename(compat.at(w).declaredName);
    } else if (!es && isUntranslatedCompatBuiltin(w)) {
      return located(t.begin, "'" + w + "' is fixed-function state of the compatibility profile that stereoshift "
                              "cannot translate (only the transform matrices, vertex attributes, colours, "
                              "texture coordinates and fog coordinate are); pass it as a uniform of your own");
    } else if (!es && isCompatBuiltin(w)) {
      // A compatibility built-in of another stage (gl_Vertex in a fragment shader).
      return located(t.begin, "'" + w + "' is not available in a " + std::string(stageName(stage)) + " shader");
    } else if (w.starts_with("gl_")) {
      // A core built-in: unchanged.
    } else if (oneXX && isNewKeyword(w, es)) {
      rename(w + "_stereoshift");
    }
  }

  // The declarations, at the start of the first line of code outside any #if.
  std::string decls;
  auto outPrecision = es ? std::string("mediump ") : std::string();
  if (fragColor && fragData) {
    auto at = std::find_if(s.identifiers.begin(), s.identifiers.end(), [](const Token& t) { return t.text == "gl_FragData"; });
    return located(at->begin, "a shader may write gl_FragColor or gl_FragData, not both");
  }
  if (fragColor) decls += "out " + outPrecision + "vec4 stereoshift_FragColor; ";
  if (fragData) decls += "out " + outPrecision + "vec4 stereoshift_FragData[gl_MaxDrawBuffers]; ";
  for (const auto& name : declare) {
    const CompatBuiltin& b = compat.at(name);
    decls += b.storage + " " + b.type + " " + b.declaredName + (b.arraySize.empty() ? "" : "[" + b.arraySize + "]") + "; ";
    result.declared.push_back(b.declaredName);
  }
  for (const auto& h : kShadowHelpers) {
    if (!helpers.count(h.name)) continue;
    decls += std::string("vec4 stereoshift_") + h.name + "(" + h.sampler + " s, " + h.coord + " c" +
             (h.lod ? ", float lod" : "") + ") { return vec4(" + h.call + "(s, c" + (h.lod ? ", lod" : "") + ")); } ";
  }
  if (!decls.empty()) {
    size_t at = s.codeLineStarts.empty() ? text.size() : s.codeLineStarts.front();
    edits.push_back({at, at, decls});
  }
  // By offset; an insertion goes before a replacement that starts where it is inserted.
  std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
    if (a.begin != b.begin) return a.begin < b.begin;
    return a.end == a.begin && b.end != b.begin;
  });
  std::string out;
  size_t pos = 0;
  if (!dialect.versionWritten) out += es ? "#version 310 es\n#line 1\n" : "#version 330\n#line 1\n";
  for (const auto& e : edits) {
    if (e.begin < pos) continue;  // overlapping (inside a replaced call): the first one wins
    out.append(text, pos, e.begin - pos);
    out += e.replacement;
    pos = e.end;
  }
  out.append(text, pos, std::string::npos);
  result.text = std::move(out);
  result.ok = true;
  return result;
}

bool verifyLegacyCompiles(const std::string& text, Stage stage, int version, bool es, const std::string& displayName,
                          Diagnostics& diags) {
  ensureGlslangInitialized();
  EShLanguage lang = EShLangVertex;
  switch (stage) {
    case Stage::Fragment: lang = EShLangFragment; break;
    case Stage::Geometry: lang = EShLangGeometry; break;
    default: break;
  }
  glslang::TShader shader(lang);
  const char* strings[] = {text.c_str()};
  const char* names[] = {displayName.c_str()};
  const int lengths[] = {static_cast<int>(text.size())};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  // AST only, no SPIR-V client: glslang's built-ins for 1xx parse only without one (with one it
  // prints its whole built-in text to stdout and fails).
  EProfile profile = es ? EEsProfile : (version >= 150 ? ECoreProfile : ENoProfile);
  glslang::TShader::ForbidIncluder noIncludes;
  bool parsed = shader.parse(GetDefaultResources(), version, profile, false, false, EShMsgDefault, noIncludes);
  return linkParsedShader(shader, parsed, EShMsgDefault, displayName, text, diags);
}

}  // namespace stereoshift
