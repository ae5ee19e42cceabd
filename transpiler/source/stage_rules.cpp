// The stage and file-name rules (see stage_rules.h): how a shader's stage is told from its name,
// -S and its `#pragma shader_stage`, the pipeline it belongs to, where its #include files are.
#include "transpiler/source/stage_rules.h"

#include "transpiler/source/lexer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <tuple>

namespace stereoshift {

namespace {

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Extensions that name a language, not a stage: the stage is in the rest of the name (.spv: a
// binary whose module says its stage; kept so `a.vert.spv` reads as before).
bool isLanguageExtension(const std::string& lowerExtension) {
  return lowerExtension == "glsl" || lowerExtension == "hlsl" || lowerExtension == "fx" || lowerExtension == "spv";
}

// A stage extension: a stage token (stageFromName), optionally followed by `shader`
// (.vertexshader, .pixelshader) or by `h` (.vsh .fsh .gsh .csh). Mesh and task names take no `h`:
// .msh is a mesh file format, not a shader.
std::optional<Stage> stageFromExtension(const std::string& lowerExtension) {
  if (auto stage = stageFromName(lowerExtension)) return stage;
  for (const std::string suffix : {"shader", "h"}) {
    if (lowerExtension.size() <= suffix.size() || !lowerExtension.ends_with(suffix)) continue;
    auto stage = stageFromName(lowerExtension.substr(0, lowerExtension.size() - suffix.size()));
    if (stage && !(suffix == "h" && (*stage == Stage::Mesh || *stage == Stage::Task))) return stage;
  }
  return std::nullopt;
}

// The words of a file-name stem that may name a stage when no extension does. Only words that are
// stage names in shader collections and rarely anything else: not `mesh` (skinned_mesh.hlsl),
// `geometry` (geometry_pass: a G-buffer pass), `domain` (domain warping) or `fs` (fs_quad: a
// full-screen quad), which stay extensions only.
std::optional<Stage> stageFromNameWord(const std::string& lowerWord) {
  static const std::map<std::string, Stage> words = {
      {"vs", Stage::Vertex},       {"vert", Stage::Vertex},         {"vertex", Stage::Vertex},
      {"ps", Stage::Fragment},     {"frag", Stage::Fragment},       {"fragment", Stage::Fragment},
      {"pixel", Stage::Fragment},  {"gs", Stage::Geometry},         {"geom", Stage::Geometry},
      {"hs", Stage::TessControl},  {"tesc", Stage::TessControl},    {"ds", Stage::TessEvaluation},
      {"tese", Stage::TessEvaluation}, {"cs", Stage::Compute},      {"comp", Stage::Compute}};
  auto it = words.find(lowerWord);
  if (it == words.end()) return std::nullopt;
  return it->second;
}

struct Word {
  size_t begin, end;
};

// The words of `stem`: split at '.', '_', '-' and ' ', and where the case changes: `basicVS` ->
// basic|VS, `VSMain` -> VS|Main, `SkinnedPixel` -> Skinned|Pixel.
std::vector<Word> splitWords(const std::string& stem) {
  std::vector<Word> words;
  auto isSeparator = [](char c) { return c == '.' || c == '_' || c == '-' || c == ' '; };
  auto upper = [](char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; };
  auto lower = [](char c) { return std::islower(static_cast<unsigned char>(c)) != 0; };
  size_t begin = 0;
  for (size_t i = 0; i <= stem.size(); ++i) {
    bool boundary = i == stem.size() || isSeparator(stem[i]);
    bool caseChange = !boundary && i > begin &&
                      ((lower(stem[i - 1]) && upper(stem[i])) ||
                       (upper(stem[i - 1]) && upper(stem[i]) && i + 1 < stem.size() && lower(stem[i + 1])));
    if (boundary || caseChange) {
      if (i > begin) words.push_back({begin, i});
      begin = boundary ? i + 1 : i;
    }
  }
  return words;
}

// `stem` without the word `w` and one separator beside it (water_vs -> water, VS_water -> water).
std::string withoutWord(const std::string& stem, Word w) {
  auto isSeparator = [](char c) { return c == '.' || c == '_' || c == '-' || c == ' '; };
  size_t begin = w.begin, end = w.end;
  if (begin > 0 && isSeparator(stem[begin - 1])) --begin;
  else if (end < stem.size() && isSeparator(stem[end])) ++end;
  std::string rest = stem.substr(0, begin) + stem.substr(end);
  return rest.empty() ? stem : rest;
}

}  // namespace

bool isIncludeOnlyName(const std::string& path) {
  std::string file = lowerCase(path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1));
  for (const char* extension : {".hlsli", ".fxh", ".inc", ".glslinc", ".glslh", ".h"})
    if (file.ends_with(extension)) return true;
  return false;
}

namespace {

// `<16 hex digits>-<kind><suffix>` with kind vs, ps, gs, hs, ds or cs: the stage of the kind.
std::optional<Stage> stageOfDumpName(const std::string& path, std::string_view suffix) {
  size_t slash = path.find_last_of('/');
  std::string_view name = std::string_view(path).substr(slash == std::string::npos ? 0 : slash + 1);
  constexpr size_t kHash = 16;
  if (name.size() != kHash + 3 + suffix.size() || name[kHash] != '-' ||
      lowerCase(std::string(name.substr(kHash + 3))) != suffix)
    return std::nullopt;
  for (size_t k = 0; k < kHash; ++k)
    if (!std::isxdigit(static_cast<unsigned char>(name[k]))) return std::nullopt;
  std::string kind = lowerCase(std::string(name.substr(kHash + 1, 2)));
  static const std::map<std::string, Stage> kinds = {{"vs", Stage::Vertex},         {"ps", Stage::Fragment},
                                                     {"gs", Stage::Geometry},       {"hs", Stage::TessControl},
                                                     {"ds", Stage::TessEvaluation}, {"cs", Stage::Compute}};
  auto it = kinds.find(kind);
  if (it == kinds.end()) return std::nullopt;
  return it->second;
}

}  // namespace

std::optional<Stage> stageOfDecompiledDump(const std::string& path) { return stageOfDumpName(path, "_replace.txt"); }

std::optional<Stage> stageOf3DMigotoDump(const std::string& path) {
  if (auto decompiled = stageOfDecompiledDump(path)) return decompiled;
  return stageOfDumpName(path, ".txt");
}

StagedName readStagedName(const std::string& path, const std::map<std::string, Stage>& extraExtensions) {
  size_t slash = path.find_last_of('/');
  std::string directory = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::string rest = path.substr(directory.size());
  StagedName named;
  named.key = path;
  if (isIncludeOnlyName(path)) return named;
  // A 3Dmigoto dump is a pipeline of its own (each shader has its own hash).
  if (auto dumped = stageOf3DMigotoDump(path)) {
    named.stage = dumped;
    named.reason = "3Dmigoto dump name " + rest;
    return named;
  }
  auto lastExtension = [&](const std::string& name) -> std::string {
    size_t dot = name.find_last_of('.');
    return dot == std::string::npos || dot == 0 ? "" : name.substr(dot + 1);
  };
  std::string languageExtension;
  if (std::string e = lowerCase(lastExtension(rest)); isLanguageExtension(e) && !extraExtensions.count(e)) {
    languageExtension = lastExtension(rest);
    rest.resize(rest.size() - languageExtension.size() - 1);
  }
  named.key = directory + rest;
  if (std::string written = lastExtension(rest); !written.empty()) {
    std::string e = lowerCase(written);
    auto extra = extraExtensions.find(e);
    std::optional<Stage> stage = extra != extraExtensions.end() ? std::optional<Stage>(extra->second) : stageFromExtension(e);
    if (stage) {
      named.stage = stage;
      named.key = directory + rest.substr(0, rest.size() - written.size() - 1);
      named.reason = "extension ." + written + (languageExtension.empty() ? "" : "." + languageExtension) +
                     (extra != extraExtensions.end() ? " (--stage-ext / [stages])" : "");
      return named;
    }
  }
  // The stage as a separate word of the name: only beside a language extension, so that
  // `notes_vs.txt` or `build_cs.py` in a shader tree are never taken for shaders.
  if (languageExtension.empty() || lowerCase(languageExtension) == "spv") return named;
  std::vector<Word> words = splitWords(rest);
  for (size_t i = words.size(); i-- > 0;) {
    std::string word = rest.substr(words[i].begin, words[i].end - words[i].begin);
    if (auto stage = stageFromNameWord(lowerCase(word))) {
      named.stage = stage;
      named.key = directory + withoutWord(rest, words[i]);
      named.reason = "name part '" + word + "' of " + path.substr(directory.size());
      return named;
    }
  }
  return named;
}

StageDecision stageFromPragma(const std::string& text) {
  StageDecision d;
  // A file that never spells `shader_stage` and splices no lines (a backslash before a line end
  // could split the word) has no such pragma: not lexed (a tenth of a no-op rebuild of a tree).
  if (text.find("shader_stage") == std::string::npos && text.find("\\\n") == std::string::npos &&
      text.find("\\\r\n") == std::string::npos)
    return d;
  source::Lexer lexer(text);
  source::Token t;
  while (lexer.next(t)) {
    if (t.kind != source::TokenKind::Directive || t.directive != source::DirectiveKind::Pragma) continue;
    const size_t lineEnd = t.end;
    std::vector<source::Token> words = lexer.directiveWords();
    auto is = [&](size_t k, std::string_view expected) {
      return k < words.size() && source::spelledString(text, words[k]) == expected;
    };
    if (!is(1, "shader_stage") || !is(2, "(")) continue;
    // The stage name: the word after `(` (a number too, so `shader_stage(3)` says what it got).
    bool named = words.size() > 3 && (words[3].kind == source::TokenKind::Identifier ||
                                      words[3].kind == source::TokenKind::Number);
    std::string name = named ? source::spelledString(text, words[3]) : "";
    size_t nameBegin = words.size() > 3 ? words[3].begin : lineEnd;
    d.stage = stageFromName(name);
    if (!d.stage || !is(named ? 4 : 3, ")")) {
      d.stage.reset();
      d.problem = "#pragma shader_stage(" + name + "): unknown stage '" + name +
                  "' (vertex, fragment, tesscontrol, tesseval, geometry, compute, mesh, task)";
      std::tie(d.problemLine, d.problemColumn) = source::lineAndColumn(text, nameBegin);
      return d;
    }
    d.reason = "#pragma shader_stage(" + name + ")";
    return d;
  }
  return d;
}

StageDecision decideStage(const std::string& path, const std::string& text, std::optional<Stage> flag,
                          const std::map<std::string, Stage>& extraExtensions) {
  StageDecision d;
  if (flag) {
    d.stage = flag;
    d.reason = std::string("-S ") + stageName(*flag);
    return d;
  }
  d = stageFromPragma(text);
  if (d.stage || !d.problem.empty()) return d;
  StagedName named = readStagedName(path, extraExtensions);
  d.stage = named.stage;
  d.reason = named.reason;
  return d;
}

std::string stageHint(const std::string& path) {
  std::string file = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  std::string why = isIncludeOnlyName(path) ? "'" + file + "' is named as an include file, not a shader stage"
                                            : "cannot tell the shader stage of '" + file + "'";
  return why + ": give it with -S <stage> (vert, tesc, tese, geom, frag, comp, mesh, task, rgen, rint, rahit, rchit, rmiss, rcall), put "
               "`#pragma shader_stage(vertex)` (or fragment, compute, ...) in the text, or name the file by "
               "its stage (name.vert, name.frag.glsl, nameVS.hlsl, name_ps.hlsl)";
}

std::vector<std::string> includeSearchPath(const std::string& shaderPath, const std::vector<std::string>& userDirs) {
  std::vector<std::string> dirs = userDirs;
  auto add = [&](const std::string& dir) {
    if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
  };
  namespace fs = std::filesystem;
  fs::path dir = fs::path(shaderPath).parent_path();
  add(dir.empty() ? "." : dir.string());
  std::error_code ec;
  fs::path beside = (dir.empty() ? fs::path(".") : dir) / "include";
  if (fs::is_directory(beside, ec)) add(dir.empty() ? std::string("include") : beside.string());
  return dirs;
}

std::string pipelineKey(const std::string& path, const std::map<std::string, Stage>& extraExtensions) {
  return readStagedName(path, extraExtensions).key;
}

std::optional<Stage> stageFromName(const std::string& raw) {
  std::string n = lowerCase(raw);
  if (n == "vert" || n == "vertex" || n == "vs") return Stage::Vertex;
  if (n == "tesc" || n == "tesscontrol" || n == "tcs" || n == "hs" || n == "hull") return Stage::TessControl;
  if (n == "tese" || n == "tesseval" || n == "tessevaluation" || n == "tes" || n == "ds" || n == "domain")
    return Stage::TessEvaluation;
  if (n == "geom" || n == "geometry" || n == "gs") return Stage::Geometry;
  if (n == "frag" || n == "fragment" || n == "fs" || n == "ps" || n == "pixel") return Stage::Fragment;
  if (n == "comp" || n == "compute" || n == "cs") return Stage::Compute;
  if (n == "mesh" || n == "ms") return Stage::Mesh;
  if (n == "task" || n == "as" || n == "amplification") return Stage::Task;
  // glslc's names of the ray-tracing stages (and their long forms).
  if (n == "rgen" || n == "raygen") return Stage::RayGen;
  if (n == "rint" || n == "intersect" || n == "intersection") return Stage::Intersection;
  if (n == "rahit" || n == "anyhit") return Stage::AnyHit;
  if (n == "rchit" || n == "closesthit") return Stage::ClosestHit;
  if (n == "rmiss" || n == "miss") return Stage::Miss;
  if (n == "rcall" || n == "callable") return Stage::Callable;
  return std::nullopt;
}

std::optional<Stage> stageFromPath(const std::string& path, const std::map<std::string, Stage>& extraExtensions) {
  return readStagedName(path, extraExtensions).stage;
}

std::optional<TargetEnv> targetEnvFromName(const std::string& name) {
  if (name == "vulkan" || name == "vulkan1.0") return TargetEnv::Vulkan1_0;
  if (name == "vulkan1.1") return TargetEnv::Vulkan1_1;
  if (name == "vulkan1.2") return TargetEnv::Vulkan1_2;
  if (name == "vulkan1.3") return TargetEnv::Vulkan1_3;
  if (name == "opengl" || name == "opengl4.5") return TargetEnv::OpenGL45;
  return std::nullopt;
}

Stage stageFromHlslProfile(std::string_view profile) {
  if (profile.size() < 3 || profile[2] != '_') return Stage::Unknown;
  std::string kind;
  for (char c : profile.substr(0, 2)) kind += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (kind == "vs") return Stage::Vertex;
  if (kind == "ps") return Stage::Fragment;
  if (kind == "gs") return Stage::Geometry;
  if (kind == "hs") return Stage::TessControl;
  if (kind == "ds") return Stage::TessEvaluation;
  if (kind == "cs") return Stage::Compute;
  return Stage::Unknown;
}

}  // namespace stereoshift
