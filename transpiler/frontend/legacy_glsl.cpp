// This turns ESSL 100 and desktop GLSL 110-150 into ESSL 310 / GLSL 330 for analysis: see legacy_glsl.h.
#include "transpiler/frontend/legacy_glsl.h"

#include "core/crash_phase.h"
#include "transpiler/frontend/glsl_lift.h"
#include "transpiler/source/lexer.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>

namespace stereoshift {

namespace {

// One identifier of the source with what surrounds it, enough for a token-level rewrite.
struct Token {
  size_t index = 0;           // in Scan::lexed
  size_t begin = 0, end = 0;  // bytes
  std::string text;           // as spelled (line splices removed)
  bool inDirective = false;   // inside a preprocessor line (a #define body)
  bool underGlEs = false;     // inside `#ifdef GL_ES` / `#if defined(GL_ES)`
};

struct Directive {
  size_t begin = 0, end = 0;  // the whole logical line, without its line break
  source::DirectiveKind kind = source::DirectiveKind::None;
  std::string rest;           // text after the name
};

// The identifiers and directives of `text` as the lexer reads them (comments left out), and where
// declarations may go in.
struct Scan {
  explicit Scan(const std::string& text);

  source::LexedText lexed;
  std::vector<Token> identifiers;
  std::vector<Directive> directives;
  // The start of the first line holding code outside any #if (npos: none). A line starts after a line
  // break between tokens: never inside a comment, a directive or after a splice.
  size_t firstCodeLine = std::string::npos;
};

// The last line break in [from, to) (blanks and splices between two tokens) that no splice hides.
size_t lastLineBreak(const std::string& text, size_t from, size_t to) {
  for (size_t k = to; k > from; --k) {
    if (text[k - 1] != '\n') continue;
    size_t b = k - 1;
    bool spliced = (b >= 1 && text[b - 1] == '\\') || (b >= 2 && text[b - 1] == '\r' && text[b - 2] == '\\');
    if (!spliced) return b;
  }
  return std::string::npos;
}

Scan::Scan(const std::string& text) : lexed(text) {
  std::vector<bool> glEsStack;  // per open #if: whether it tests GL_ES
  auto underGlEs = [&] { return std::find(glEsStack.begin(), glEsStack.end(), true) != glEsStack.end(); };
  size_t lineStart = 0, seen = 0, directiveName = std::string::npos;
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.begin > seen)
      if (size_t lineBreak = lastLineBreak(text, seen, t.begin); lineBreak != std::string::npos) lineStart = lineBreak + 1;
    seen = std::max(seen, t.end);
    if (t.kind == source::TokenKind::Comment) continue;
    if (t.kind == source::TokenKind::Directive) {
      Directive d;
      d.begin = t.begin;
      d.end = t.end;
      d.kind = t.directive;
      directiveName = lexed.directiveName(k).empty() ? std::string::npos : lexed.nextNonComment(k);
      size_t restBegin = directiveName != std::string::npos ? lexed[directiveName].end : t.begin + 1;
      d.rest = text.substr(restBegin, d.end - restBegin);
      bool testsGlEs = d.rest.find("GL_ES") != std::string::npos;
      using source::DirectiveKind;
      if (d.kind == DirectiveKind::If || d.kind == DirectiveKind::Ifdef || d.kind == DirectiveKind::Ifndef) {
        glEsStack.push_back(d.kind != DirectiveKind::Ifndef && testsGlEs);
      } else if (d.kind == DirectiveKind::Endif) {
        if (!glEsStack.empty()) glEsStack.pop_back();
      } else if (d.kind == DirectiveKind::Else || d.kind == DirectiveKind::Elif) {
        if (!glEsStack.empty()) glEsStack.back() = false;
      }
      directives.push_back(std::move(d));
      continue;
    }
    if (t.inDirective()) {
      // Macro bodies are code: their identifiers (the macro's name too) are rewritten like any other.
      if (t.directive == source::DirectiveKind::Define && t.kind == source::TokenKind::Identifier && k != directiveName)
        identifiers.push_back({k, t.begin, t.end, source::spelledString(text, t), true, underGlEs()});
      continue;
    }
    if (firstCodeLine == std::string::npos && t.ifDepth == 0) firstCodeLine = lineStart;
    if (t.kind == source::TokenKind::Identifier)
      identifiers.push_back({k, t.begin, t.end, source::spelledString(text, t), false, underGlEs()});
  }
}

// Extensions whose features ESSL 300 has in core: the translation drops their #extension lines.
bool isCoreInEssl300(const std::string& extension) {
  return extension == "GL_OES_standard_derivatives" || extension == "GL_EXT_shader_texture_lod" ||
         extension == "GL_EXT_frag_depth" || extension == "GL_EXT_draw_buffers";
}

// The extension an #extension line names: the first identifier after the directive's name.
std::string extensionName(const std::string& rest) {
  size_t i = 0;
  while (i < rest.size() && !isIdentifierStart(rest[i])) ++i;
  size_t b = i;
  while (i < rest.size() && isIdentifierChar(rest[i])) ++i;
  return rest.substr(b, i - b);
}

// 1xx texture lookups and their ESSL 300 / GLSL 130 names.
const std::map<std::string, std::string>& textureRenames() {
  static const std::map<std::string, std::string> renames = [] {
    std::map<std::string, std::string> m;
    for (const char* dim : {"1D", "2D", "3D", "Cube", "2DRect", "1DArray", "2DArray"}) {
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

// Desktop shadow lookups return a vec4 in 1xx and a float from `texture`: helpers keep the vec4. The
// 1xx forms with a LOD bias (fragment stage), the rectangle and array forms of GL_ARB_texture_rectangle
// and GL_EXT_texture_array, and GL_ARB_shader_texture_lod's gradients, each an overload of its name.
struct ShadowHelper {
  const char* name;
  const char* sampler;
  const char* coord;
  const char* call;    // the 130 function
  const char* params;  // after the coordinate: ", float lod", ...
  const char* args;    // the same, passed on: ", lod", ...
  bool fragmentOnly;   // a bias: implicit derivatives
};
const ShadowHelper kShadowHelpers[] = {
    {"shadow1D", "sampler1DShadow", "vec3", "texture", "", "", false},
    {"shadow1D", "sampler1DShadow", "vec3", "texture", ", float bias", ", bias", true},
    {"shadow1DProj", "sampler1DShadow", "vec4", "textureProj", "", "", false},
    {"shadow1DProj", "sampler1DShadow", "vec4", "textureProj", ", float bias", ", bias", true},
    {"shadow1DLod", "sampler1DShadow", "vec3", "textureLod", ", float lod", ", lod", false},
    {"shadow1DProjLod", "sampler1DShadow", "vec4", "textureProjLod", ", float lod", ", lod", false},
    {"shadow2D", "sampler2DShadow", "vec3", "texture", "", "", false},
    {"shadow2D", "sampler2DShadow", "vec3", "texture", ", float bias", ", bias", true},
    {"shadow2DProj", "sampler2DShadow", "vec4", "textureProj", "", "", false},
    {"shadow2DProj", "sampler2DShadow", "vec4", "textureProj", ", float bias", ", bias", true},
    {"shadow2DLod", "sampler2DShadow", "vec3", "textureLod", ", float lod", ", lod", false},
    {"shadow2DProjLod", "sampler2DShadow", "vec4", "textureProjLod", ", float lod", ", lod", false},
    {"shadow2DRect", "sampler2DRectShadow", "vec3", "texture", "", "", false},
    {"shadow2DRectProj", "sampler2DRectShadow", "vec4", "textureProj", "", "", false},
    {"shadow1DArray", "sampler1DArrayShadow", "vec3", "texture", "", "", false},
    {"shadow1DArray", "sampler1DArrayShadow", "vec3", "texture", ", float bias", ", bias", true},
    {"shadow1DArrayLod", "sampler1DArrayShadow", "vec3", "textureLod", ", float lod", ", lod", false},
    {"shadow2DArray", "sampler2DArrayShadow", "vec4", "texture", "", "", false},
    {"shadow1DGradARB", "sampler1DShadow", "vec3", "textureGrad", ", float dx, float dy", ", dx, dy", false},
    {"shadow1DProjGradARB", "sampler1DShadow", "vec4", "textureProjGrad", ", float dx, float dy", ", dx, dy", false},
    {"shadow2DGradARB", "sampler2DShadow", "vec3", "textureGrad", ", vec2 dx, vec2 dy", ", dx, dy", false},
    {"shadow2DProjGradARB", "sampler2DShadow", "vec4", "textureProjGrad", ", vec2 dx, vec2 dy", ", dx, dy", false},
    {"shadow2DRectGradARB", "sampler2DRectShadow", "vec3", "textureGrad", ", vec2 dx, vec2 dy", ", dx, dy", false},
    {"shadow2DRectProjGradARB", "sampler2DRectShadow", "vec4", "textureProjGrad", ", vec2 dx, vec2 dy", ", dx, dy",
     false},
};

// A compatibility built-in the translation declares: `storage type stereoshift_<name>[array]`.
struct CompatBuiltin {
  std::string storage;  // "in", "out" or "uniform"
  std::string type;
  std::string declaredName;  // stereoshift_...
  std::string arraySize;     // "" for none
  std::string structure;     // the struct `type` names, declared before it ("" for a plain type)
};

// The fixed-function state of the compatibility profile as uniform structs, as the GLSL 1.10-1.50
// specifications list their members, each struct named stereoshift_<the specification's name>:
// the analysis reads the shader's own uses of them (`gl_LightSource[0].position`), the output keeps
// the shader's text. The arrays are sized by the limits every driver has at least of (8 lights, 8
// texture coordinate sets and units, 8 clip planes; the shader's own indices are its own business).
struct FixedFunctionStruct {
  const char* name;
  const char* members;
};
const FixedFunctionStruct kFixedFunctionStructs[] = {
    {"LightSourceParameters",
     "vec4 ambient; vec4 diffuse; vec4 specular; vec4 position; vec4 halfVector; vec3 spotDirection; "
     "float spotExponent; float spotCutoff; float spotCosCutoff; float constantAttenuation; "
     "float linearAttenuation; float quadraticAttenuation;"},
    {"LightModelParameters", "vec4 ambient;"},
    {"LightModelProducts", "vec4 sceneColor;"},
    {"LightProducts", "vec4 ambient; vec4 diffuse; vec4 specular;"},
    {"MaterialParameters", "vec4 emission; vec4 ambient; vec4 diffuse; vec4 specular; float shininess;"},
    {"FogParameters", "vec4 color; float density; float start; float end; float scale;"},
    {"PointParameters",
     "float size; float sizeMin; float sizeMax; float fadeThresholdSize; float distanceConstantAttenuation; "
     "float distanceLinearAttenuation; float distanceQuadraticAttenuation;"},
};

std::string fixedFunctionStruct(const std::string& name) {
  for (const auto& s : kFixedFunctionStructs)
    if (name == s.name) return std::string("struct stereoshift_") + s.name + " { " + s.members + " };";
  return "";
}

// The compatibility built-ins of desktop GLSL 1xx, as `stage` sees them.
std::map<std::string, CompatBuiltin> compatBuiltins(Stage stage) {
  std::map<std::string, CompatBuiltin> m;
  auto add = [&](const std::string& glName, const std::string& storage, const std::string& type,
                 const std::string& declared, const std::string& array = "") {
    m[glName] = {storage, type, "stereoshift_" + declared, array, ""};
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
  // Fixed-function lighting, material, fog and point state, clip and texture-generation planes.
  auto addState = [&](const std::string& glName, const std::string& structName, const std::string& array = "") {
    add(glName, "uniform", "stereoshift_" + structName, glName.substr(3), array);
    m[glName].structure = structName;
  };
  addState("gl_LightSource", "LightSourceParameters", "8");
  addState("gl_LightModel", "LightModelParameters");
  addState("gl_FrontLightModelProduct", "LightModelProducts");
  addState("gl_BackLightModelProduct", "LightModelProducts");
  addState("gl_FrontLightProduct", "LightProducts", "8");
  addState("gl_BackLightProduct", "LightProducts", "8");
  addState("gl_FrontMaterial", "MaterialParameters");
  addState("gl_BackMaterial", "MaterialParameters");
  addState("gl_Fog", "FogParameters");
  addState("gl_Point", "PointParameters");
  add("gl_ClipPlane", "uniform", "vec4", "ClipPlane", "8");
  add("gl_TextureEnvColor", "uniform", "vec4", "TextureEnvColor", "8");
  for (const char* plane : {"gl_EyePlaneS", "gl_EyePlaneT", "gl_EyePlaneR", "gl_EyePlaneQ", "gl_ObjectPlaneS",
                            "gl_ObjectPlaneT", "gl_ObjectPlaneR", "gl_ObjectPlaneQ"})
    add(plane, "uniform", "vec4", std::string(plane).substr(3), "8");
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
  static const std::set<std::string> names = {"gl_FrontColorIn", "gl_BackColorIn", "gl_TexCoordIn",
                                              "gl_FogFragCoordIn", "gl_SecondaryColorIn"};
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

// The built-in functions ESSL 3.10 has and ESSL 1.00 does not (with GL_EXT_gpu_shader5, which the
// front end enables for the translation's parse). WebGL1 code often defines the ones it lacks
// itself (`inverse`, `transpose`, `round`): plain user functions in ESSL 1.00, but glslang parses
// the translation as ESSL 3.10, where they would redefine built-ins (an error in ESSL 3). A
// function named like an ESSL 1.00 built-in is another matter: redefining one is an error in ESSL
// 1.00 too (Mesa says so), and an overload of one stays glslang's refusal.
bool isBuiltinOnlyAfterEssl100(const std::string& name) {
  static const std::set<std::string> names = {
      // trigonometry, common
      "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "trunc", "round", "roundEven", "modf", "isnan", "isinf",
      "floatBitsToInt", "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat", "fma", "frexp", "ldexp",
      // packing
      "packSnorm2x16", "unpackSnorm2x16", "packUnorm2x16", "unpackUnorm2x16", "packHalf2x16", "unpackHalf2x16",
      "packUnorm4x8", "packSnorm4x8", "unpackUnorm4x8", "unpackSnorm4x8",
      // matrix
      "outerProduct", "transpose", "determinant", "inverse",
      // integer
      "uaddCarry", "usubBorrow", "umulExtended", "imulExtended", "bitfieldExtract", "bitfieldInsert",
      "bitfieldReverse", "bitCount", "findLSB", "findMSB",
      // texture (`texture` itself is renamed as a new keyword)
      "textureSize", "textureProj", "textureLod", "textureOffset", "texelFetch", "texelFetchOffset",
      "textureProjOffset", "textureLodOffset", "textureProjLod", "textureProjLodOffset", "textureGrad",
      "textureGradOffset", "textureProjGrad", "textureProjGradOffset", "textureGather", "textureGatherOffset",
      "textureGatherOffsets",
      // atomics, images, interpolation, barriers
      "atomicCounterIncrement", "atomicCounterDecrement", "atomicCounter", "atomicAdd", "atomicMin", "atomicMax",
      "atomicAnd", "atomicOr", "atomicXor", "atomicExchange", "atomicCompSwap", "imageSize", "imageLoad",
      "imageStore", "imageAtomicAdd", "imageAtomicMin", "imageAtomicMax", "imageAtomicAnd", "imageAtomicOr",
      "imageAtomicXor", "imageAtomicExchange", "imageAtomicCompSwap", "interpolateAtCentroid",
      "interpolateAtSample", "interpolateAtOffset", "barrier", "memoryBarrier", "memoryBarrierAtomicCounter",
      "memoryBarrierBuffer", "memoryBarrierImage", "memoryBarrierShared", "groupMemoryBarrier"};
  return names.count(name) > 0;
}

// The code token before `k` (comments skipped; a macro body's tokens count as code); npos: none.
size_t previousCodeToken(const source::LexedText& lexed, size_t k) {
  while (k-- > 0)
    if (lexed[k].kind != source::TokenKind::Comment) return k;
  return std::string::npos;
}

// The names of ESSL 3.10 built-ins ESSL 1.00 lacks that `scan`'s text declares or defines at file
// scope (a type word, the name, `(`, outside every brace): in ESSL 100 they name the user's functions.
std::set<std::string> builtinFunctionsDefined(const Scan& scan) {
  std::set<std::string> defined;
  const source::LexedText& lexed = scan.lexed;
  int depth = 0;
  for (size_t k = 0; k < lexed.size(); ++k) {
    if (!lexed[k].isCode()) continue;
    if (lexed.isPunct(k, '{')) ++depth;
    if (lexed.isPunct(k, '}')) depth = std::max(0, depth - 1);
    if (depth != 0 || !lexed.isIdentifier(k) || !lexed.isPunct(lexed.nextNonComment(k), '(')) continue;
    std::string name(lexed.text(k));
    size_t before = previousCodeToken(lexed, k);
    if (isBuiltinOnlyAfterEssl100(name) && before != std::string::npos && lexed.isIdentifier(before) &&
        lexed[before].isCode())
      defined.insert(std::move(name));
  }
  return defined;
}

// How many braces are open at token `k` (code tokens only).
int braceDepthAt(const source::LexedText& lexed, size_t k) {
  int depth = 0;
  for (size_t i = 0; i < k && i < lexed.size(); ++i) {
    if (!lexed[i].isCode()) continue;
    if (lexed.isPunct(i, '{')) ++depth;
    if (lexed.isPunct(i, '}')) depth = std::max(0, depth - 1);
  }
  return depth;
}

// `name` at `t` names a function, not a member selected after `.`.
bool isFreeName(const source::LexedText& lexed, const Token& t) {
  size_t before = previousCodeToken(lexed, t.index);
  return before == std::string::npos || !lexed.isPunct(before, '.');
}

// `text` with each user function named like an ESSL 3 built-in ESSL 1.00 lacks renamed
// (name_stereoshift) wherever it is named: glslang refuses such a definition at every ES version.
std::string renameUserBuiltins(const std::string& text) {
  Scan scan(text);
  std::set<std::string> defined = builtinFunctionsDefined(scan);
  if (defined.empty()) return text;
  std::string out;
  size_t pos = 0;
  for (const Token& t : scan.identifiers) {
    if (!defined.count(t.text) || !isFreeName(scan.lexed, t)) continue;
    out.append(text, pos, t.end - pos);
    out += "_stereoshift";
    pos = t.end;
  }
  out.append(text, pos, std::string::npos);
  return out;
}

// The matrix type names GLSL 1.20 made keywords (mat2x2 ... mat4x4): plain names in a GLSL 110 text.
bool isMatrixTypeSince120(const std::string& word) {
  return word.size() == 6 && word.compare(0, 3, "mat") == 0 && word[4] == 'x' && word[3] >= '2' && word[3] <= '4' &&
         word[5] >= '2' && word[5] <= '4';
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
    // The compatibility profile at any version: glslang makes no SPIR-V from it (and refuses its
    // built-ins), so the same translation to core, at the shader's own version from 330 on.
    d.legacy = d.es ? d.version < 300 : d.version < 330 || version.compatibility;
    d.reason = "#version " + std::to_string(d.version) + (d.es && d.version != 100 ? " es" : "") +
               (version.compatibility ? " compatibility" : "");
    return d;
  }
  // No #version: GLSL's default is 110, ESSL's 100; what the text uses decides between them.
  d.legacy = true;
  Scan s(text);
  for (const auto& t : s.identifiers) {
    if (t.text == "ftransform" || isCompatBuiltin(t.text)) {
      d.version = 110;
      d.reason = "no #version; uses the desktop compatibility built-in " + t.text + ", so GLSL's default 110";
      return d;
    }
  }
  for (const auto& dir : s.directives) {
    if (dir.kind == source::DirectiveKind::Extension) {
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
  d.byDefault = true;
  return d;
}

void settleVersionlessDialect(LegacyDialect& dialect, const std::string& text, Stage stage) {
  if (dialect.versionWritten || !dialect.legacy) return;
  // Each candidate with its #version put before the text (glslang takes ESSL 300 on only so), the
  // lines numbered as written.
  auto versioned = [&](int version, bool es) {
    return "#version " + std::to_string(version) + (es && version >= 300 ? " es" : "") + "\n#line 1\n" + text;
  };
  auto parses = [&](int version, bool es, Diagnostics& diags) {
    return verifyLegacyCompiles(versioned(version, es), stage, version, es, "", diags);
  };
  Diagnostics asDecided;
  if (parses(dialect.version, dialect.es, asDecided)) return;
  // What the decision was made from; the first error at the decided version says why not.
  const auto& errors = asDecided.all();
  auto first = std::find_if(errors.begin(), errors.end(), [](const Diagnostic& e) { return e.severity == Severity::Error; });
  const std::string why = first != errors.end() ? " (" + first->message + ")" : std::string();
  const std::string decided = dialect.es ? "ESSL 100" : "GLSL 110";
  struct Candidate {
    int version;
    bool es;
  };
  std::vector<Candidate> ladder;
  if (dialect.es) {
    ladder = {{300, true}, {310, true}, {320, true}};
  } else {
    // GLSL 110's neighbour first where nothing in the text is desktop-only: WebGL1 vertex shaders
    // need no precision statement (the vertex stage has a default) and so often show nothing ES-only.
    if (dialect.byDefault && (stage == Stage::Vertex || stage == Stage::Fragment)) ladder.push_back({100, true});
    for (int version : {120, 130, 140, 150, 330, 400, 410, 420, 430, 440, 450, 460}) ladder.push_back({version, false});
  }
  // At a version as written, or, where glslang's only objection is a built-in block redeclaration
  // (which it takes from 410 on, drivers from 150), as its lifted copy (glsl_lift.h) at that version:
  // the front end lifts it the same way.
  auto parsesAt = [&](const Candidate& c) {
    Diagnostics plain;
    if (parses(c.version, c.es, plain)) return true;
    if (c.es || c.version < 150) return false;
    for (const auto& d : plain.all())
      if (d.severity == Severity::Error && d.message.find("built-in block redeclaration") == std::string::npos &&
          d.line != 0)
        return false;
    LiftedGlsl lifted = liftGlsl(versioned(c.version, false));
    Diagnostics ignored;
    return lifted.lifted && verifyLegacyCompiles(lifted.text, stage, c.version, false, "", ignored);
  };
  for (const Candidate& c : ladder) {
    if (!parsesAt(c)) continue;
    dialect.version = c.version;
    dialect.es = c.es;
    dialect.legacy = c.es ? c.version < 300 : c.version < 330;
    dialect.byDefault = false;
    std::string name = c.es ? "ESSL " + std::to_string(c.version) : "GLSL " + std::to_string(c.version);
    dialect.reason = "no #version; glslang refuses it as " + decided + why + " and takes it as " + name + ", so " +
                     name + (c.es && c.version == 100 ? " (WebGL1)" : " (the version its loader prepends, at the least)");
    return;
  }
}

namespace {

// One translation (see translateLegacyGlsl): the edits it makes to the user's text, by offset, and
// what it has to declare for them.
class LegacyTranslator {
 public:
  LegacyTranslator(const std::string& text, Stage stage, const LegacyDialect& dialect, const std::string& path)
      : text_(text), path_(path), stage_(stage), dialect_(dialect), scan_(text), es_(dialect.es),
        fragment_(stage == Stage::Fragment), oneXX_(dialect.es || dialect.version < 130),
        compat_(dialect.es ? std::map<std::string, CompatBuiltin>{} : compatBuiltins(stage)) {}

  LegacyTranslation run() {
    rewriteDirectives();
    blankBuiltInBlockRedeclarations();
    if (es_) userBuiltins_ = builtinFunctionsDefined(scan_);
    for (const Token& t : scan_.identifiers)
      if (auto error = rewriteIdentifier(t)) return failed(*error);
    if (fragColor_ && fragData_) {
      auto at = std::find_if(scan_.identifiers.begin(), scan_.identifiers.end(),
                             [](const Token& t) { return t.text == "gl_FragData"; });
      return failed(locate(at->begin, "a shader may write gl_FragColor or gl_FragData, not both"));
    }
    LegacyTranslation result;
    if (std::string decls = declarations(result.declared); !decls.empty()) {
      // At the start of the first line of code outside any #if, so no line moves.
      size_t at = scan_.firstCodeLine == std::string::npos ? text_.size() : scan_.firstCodeLine;
      edits_.push_back({at, at, decls});
    }
    result.text = applyEdits();
    result.ok = true;
    return result;
  }

 private:
  struct Edit {
    size_t begin, end;
    std::string replacement;
  };

  Diagnostic locate(size_t offset, const std::string& message) const {
    auto [line, column] = source::lineAndColumn(text_, offset);
    return Diagnostic{Severity::Error, path_, line, column, message};
  }
  static LegacyTranslation failed(Diagnostic error) {
    LegacyTranslation result;
    result.error = std::move(error);
    return result;
  }

  void rewriteDirectives() {
    for (const auto& d : scan_.directives) {
      if (d.kind == source::DirectiveKind::Version) {
        edits_.push_back({d.begin, d.end, es_ ? "#version 310 es" : "#version " + std::to_string(coreVersion())});
      } else if (d.kind == source::DirectiveKind::Extension && es_ && isCoreInEssl300(extensionName(d.rest))) {
        edits_.push_back({d.begin, d.end, ""});  // core in ESSL 300: the line stays, empty
      }
    }
  }

  // `out gl_PerVertex { vec4 gl_Position; vec4 gl_FrontColor; };` (and `in ... gl_in[];`) with a
  // compatibility member blanked, line breaks kept: that member is no core member (the translation
  // declares it on its own), and the core built-ins it names exist without the block. One of core
  // members only stays (the lifted copy raises the version for it). The output keeps it as written.
  void blankBuiltInBlockRedeclarations() {
    const source::LexedText& lexed = scan_.lexed;
    for (size_t k = 0; k < lexed.size(); ++k) {
      if (!lexed.isIdentifier(k) || !lexed[k].isCode() || lexed.text(k) != "gl_PerVertex" || k == 0) continue;
      size_t storage = k - 1;
      while (storage > 0 && lexed[storage].kind == source::TokenKind::Comment) --storage;
      size_t open = lexed.nextNonComment(k);
      if (!lexed.isIdentifier(storage) || (lexed.text(storage) != "in" && lexed.text(storage) != "out") ||
          !lexed.isPunct(open, '{'))
        continue;
      size_t end = open;
      int depth = 0;
      for (; end < lexed.size(); ++end) {
        if (lexed.isPunct(end, '{')) ++depth;
        if (lexed.isPunct(end, '}') && --depth == 0) break;
      }
      bool compatibilityMember = false;
      for (size_t m = open; m < end; ++m) compatibilityMember |= lexed.isIdentifier(m) && compat_.count(std::string(lexed.text(m)));
      while (end < lexed.size() && !lexed.isPunct(end, ';')) ++end;
      if (end >= lexed.size()) return;  // unterminated: glslang says so
      if (!compatibilityMember) continue;
      std::string blank = text_.substr(lexed[storage].begin, lexed[end].end - lexed[storage].begin);
      for (char& c : blank)
        if (c != '\n' && c != '\r') c = ' ';
      edits_.push_back({lexed[storage].begin, lexed[end].end, blank});
      k = end;
    }
  }

  // The edit for one identifier of the source, or why the text cannot be translated.
  std::optional<Diagnostic> rewriteIdentifier(const Token& t) {
    const std::string& w = t.text;
    // A name written across a line splice keeps its splices after the new name: no line moves.
    auto rename = [&](std::string to) {
      edits_.push_back({t.begin, t.end, std::move(to) + source::splicesOf(text_, scan_.lexed[t.index])});
    };
    if (userBuiltins_.count(w) && isFreeName(scan_.lexed, t)) {
      rename(w + "_stereoshift");  // the user's function, hiding the built-in of its name
    } else if (oneXX_ && w == "attribute") {
      if (stage_ != Stage::Vertex) return locate(t.begin, "'attribute' is only allowed in a vertex shader");
      rename("in");
    } else if (oneXX_ && w == "varying") {
      rename(fragment_ ? "in" : "out");
    } else if (dialect_.version >= 130 && !es_ && (w == "attribute" || w == "varying")) {
      rename(w == "attribute" ? "in" : (fragment_ ? "in" : "out"));  // deprecated in 130-150, still accepted
    } else if (auto tex = textureRenames().find(w); tex != textureRenames().end()) {
      rename(tex->second);
    } else if (!es_ && std::any_of(std::begin(kShadowHelpers), std::end(kShadowHelpers),
                                   [&](const ShadowHelper& h) { return w == h.name; })) {
      helpers_.insert(w);
      rename("stereoshift_" + w);
    } else if (w == "gl_FragColor" && fragment_) {
      fragColor_ = true;
      rename("stereoshift_FragColor");
    } else if (w == "gl_FragData" && fragment_) {
      fragData_ = true;
      rename("stereoshift_FragData");
    } else if (w == "gl_FragDepthEXT") {
      rename("gl_FragDepth");
    } else if (!es_ && w == "ftransform") {
      return rewriteFtransform(t);
    } else if (compat_.count(w)) {
      // The shader's own redeclaration of it (`varying vec4 gl_TexCoord[3];`, sizing the array, as
      // the compatibility profile allows) is the declaration: renamed, and none of ours beside it.
      // (At file scope: a member of a redeclared built-in block is not one; the analysis copy leaves
      // such a block out.)
      size_t before = previousCodeToken(scan_.lexed, t.index);
      if (before != std::string::npos && scan_.lexed.isIdentifier(before) && scan_.lexed[before].isCode() &&
          braceDepthAt(scan_.lexed, t.index) == 0)
        redeclared_.insert(w);
      declare_.insert(w);
      rename(compat_.at(w).declaredName);
    } else if (!es_ && isUntranslatedCompatBuiltin(w)) {
      return locate(t.begin, "'" + w + "' is a compatibility-profile input of the geometry stage that stereoshift "
                             "cannot translate (the other compatibility built-ins are); pass it as a varying of your own");
    } else if (!es_ && isCompatBuiltin(w)) {
      // A compatibility built-in of another stage (gl_Vertex in a fragment shader).
      return locate(t.begin, "'" + w + "' is not available in a " + std::string(stageName(stage_)) + " shader");
    } else if (w.starts_with("gl_")) {
      // A core built-in: unchanged.
    } else if ((oneXX_ && isNewKeyword(w, es_)) || (!es_ && dialect_.version < 120 && isMatrixTypeSince120(w))) {
      rename(w + "_stereoshift");
    }
    return std::nullopt;
  }

  // ftransform() -> (MVP * vertex): the call's `(` and `)` go with it.
  std::optional<Diagnostic> rewriteFtransform(const Token& t) {
    const source::LexedText& lexed = scan_.lexed;
    size_t open = lexed.nextNonComment(t.index);
    size_t close = lexed.isPunct(open, '(') ? lexed.nextNonComment(open) : lexed.size();
    if (!lexed.isPunct(close, ')')) return locate(t.begin, "ftransform must be called as `ftransform()`");
    if (stage_ != Stage::Vertex) return locate(t.begin, "ftransform() is only available in a vertex shader");
    declare_.insert("gl_ModelViewProjectionMatrix");
    declare_.insert("gl_Vertex");
    edits_.push_back({t.begin, lexed[close].end, "(stereoshift_ModelViewProjectionMatrix * stereoshift_Vertex)"});
    return std::nullopt;
  }

  // What the edits need declared, on one line; the compatibility built-ins' names into `declared`.
  std::string declarations(std::vector<std::string>& declared) const {
    std::string decls;
    auto outPrecision = es_ ? std::string("mediump ") : std::string();
    if (fragColor_) decls += "out " + outPrecision + "vec4 stereoshift_FragColor; ";
    if (fragData_) decls += "out " + outPrecision + "vec4 stereoshift_FragData[gl_MaxDrawBuffers]; ";
    std::set<std::string> structures;
    for (const auto& name : declare_) {
      if (redeclared_.count(name)) continue;
      const CompatBuiltin& b = compat_.at(name);
      if (!b.structure.empty() && structures.insert(b.structure).second) decls += fixedFunctionStruct(b.structure) + " ";
      decls += b.storage + " " + b.type + " " + b.declaredName + (b.arraySize.empty() ? "" : "[" + b.arraySize + "]") + "; ";
      declared.push_back(b.declaredName);
    }
    for (const auto& h : kShadowHelpers) {
      if (!helpers_.count(h.name) || (h.fragmentOnly && !fragment_)) continue;
      decls += std::string("vec4 stereoshift_") + h.name + "(" + h.sampler + " s, " + h.coord + " c" +
               h.params + ") { return vec4(" + h.call + "(s, c" + h.args + ")); } ";
    }
    return decls;
  }

  // The core version the translation is parsed at: 330, or the shader's own from there on (a
  // compatibility-profile shader of a later version).
  int coreVersion() const { return std::max(330, dialect_.version); }

  std::string applyEdits() {
    // By offset; an insertion goes before a replacement that starts where it is inserted.
    std::stable_sort(edits_.begin(), edits_.end(), [](const Edit& a, const Edit& b) {
      if (a.begin != b.begin) return a.begin < b.begin;
      return a.end == a.begin && b.end != b.begin;
    });
    std::string out;
    size_t pos = 0;
    if (!dialect_.versionWritten)
      out += es_ ? "#version 310 es\n#line 1\n" : "#version " + std::to_string(coreVersion()) + "\n#line 1\n";
    for (const auto& e : edits_) {
      if (e.begin < pos) continue;  // overlapping (inside a replaced call): the first one wins
      out.append(text_, pos, e.begin - pos);
      out += e.replacement;
      pos = e.end;
    }
    out.append(text_, pos, std::string::npos);
    return out;
  }

  const std::string& text_;
  const std::string& path_;
  Stage stage_;
  const LegacyDialect& dialect_;
  Scan scan_;
  bool es_, fragment_;
  bool oneXX_;  // still without in/out storage and `texture`
  std::map<std::string, CompatBuiltin> compat_;
  std::vector<Edit> edits_;
  std::set<std::string> declare_;  // compat built-ins (by gl_ name) used
  std::set<std::string> redeclared_;  // ... and declared by the shader itself (a type name before it)
  std::set<std::string> helpers_;  // shadow helpers used
  std::set<std::string> userBuiltins_;  // ESSL 100: the user's functions named like ESSL 3-only built-ins
  bool fragColor_ = false, fragData_ = false;
};

}  // namespace

LegacyTranslation translateLegacyGlsl(const std::string& text, Stage stage, const LegacyDialect& dialect,
                                      const std::string& path) {
  return LegacyTranslator(text, stage, dialect, path).run();
}

bool verifyLegacyCompiles(const std::string& text, Stage stage, int version, bool es, const std::string& displayName,
                          Diagnostics& diags) {
  ensureGlslangInitialized();
  EShLanguage lang = EShLangVertex;
  switch (stage) {
    case Stage::Fragment: lang = EShLangFragment; break;
    case Stage::Geometry: lang = EShLangGeometry; break;
    case Stage::TessControl: lang = EShLangTessControl; break;
    case Stage::TessEvaluation: lang = EShLangTessEvaluation; break;
    case Stage::Compute: lang = EShLangCompute; break;
    default: break;
  }
  glslang::TShader shader(lang);
  // ESSL 100 code may define `inverse` & co. itself; glslang refuses it (isBuiltinOnlyAfterEssl100):
  // those functions compiled under another name, the rest as written.
  const std::string compiled = es ? renameUserBuiltins(text) : text;
  // glslang ends its input at a NUL byte, even in a comment: the compiler's copy has spaces there.
  const std::string given = source::blankNuls(compiled);
  const char* strings[] = {given.c_str()};
  const char* names[] = {displayName.c_str()};
  const int lengths[] = {static_cast<int>(given.size())};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  // AST only, no SPIR-V client: glslang's built-ins for 1xx parse only without one (with one it
  // prints its whole built-in text to stdout and fails).
  EProfile profile = es ? EEsProfile : (version >= 150 ? ECoreProfile : ENoProfile);
  glslang::TShader::ForbidIncluder noIncludes;
  ScopedCrashPhase phase(kRecompilePhase);
  bool parsed = shader.parse(GetDefaultResources(), version, profile, false, false, EShMsgDefault, noIncludes);
  return linkParsedShader(shader, parsed, EShMsgDefault, displayName, text, diags);
}

}  // namespace stereoshift
