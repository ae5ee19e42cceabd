#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/glslang_log.h"
#include "transpiler/frontend/language_detect.h"
#include "passes/source_text.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {

void ensureGlslangInitialized() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

namespace {

EShLanguage toGlslang(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return EShLangVertex;
    case Stage::TessControl: return EShLangTessControl;
    case Stage::TessEvaluation: return EShLangTessEvaluation;
    case Stage::Geometry: return EShLangGeometry;
    case Stage::Fragment: return EShLangFragment;
    case Stage::Compute: return EShLangCompute;
    case Stage::Task: return EShLangTask;
    case Stage::Mesh: return EShLangMesh;
    default: return EShLangVertex;
  }
}

// Resolves #include only inside the including file's directory and the -I directories, so a
// shader tree conversion never reads outside what the user named.
class RestrictedIncluder : public glslang::TShader::Includer {
 public:
  RestrictedIncluder(std::string mainFile, std::vector<std::string> includeDirs)
      : mainFile_(std::move(mainFile)), includeDirs_(std::move(includeDirs)) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    fs::path base = (depth <= 1 || !includer || !*includer) ? fs::path(mainFile_).parent_path()
                                                            : fs::path(includer).parent_path();
    if (auto* r = tryOpen(base, header)) return r;
    return includeSystem(header, includer, depth);
  }

  IncludeResult* includeSystem(const char* header, const char*, size_t) override {
    for (const auto& dir : includeDirs_)
      if (auto* r = tryOpen(dir, header)) return r;
    return nullptr;
  }

  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

  const std::vector<std::pair<std::string, std::string>>& sources() const { return sources_; }
  const std::vector<std::string>& includedFiles() const { return included_; }

 private:
  IncludeResult* tryOpen(const fs::path& dir, const char* header) {
    fs::path candidate = (dir.empty() ? fs::path(".") : dir) / header;
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) return nullptr;
    fs::path root = fs::weakly_canonical(dir.empty() ? fs::path(".") : dir, ec);
    fs::path resolved = fs::weakly_canonical(candidate, ec);
    auto rel = resolved.lexically_relative(root);
    if (rel.empty() || *rel.begin() == "..") return nullptr;  // escapes the allowed directory
    auto* text = new std::string;
    if (!readFile(candidate.string(), text)) {
      delete text;
      return nullptr;
    }
    std::string name = candidate.lexically_normal().string();
    sources_.emplace_back(name, *text);
    if (std::find(included_.begin(), included_.end(), name) == included_.end()) included_.push_back(name);
    return new IncludeResult(name, text->data(), text->size(), text);
  }

  std::string mainFile_;
  std::vector<std::string> includeDirs_;
  std::vector<std::pair<std::string, std::string>> sources_;
  std::vector<std::string> included_;
};

}  // namespace

// A hand-written scan: a std::regex over the whole text cost more than the rest of the front end's
// reading of the source.
VersionLine findVersion(const std::string& text) {
  VersionLine v;
  auto skipBlanks = [&](size_t i) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    return i;
  };
  for (size_t line = 0, next = 0; line < text.size(); line = next) {
    size_t newline = text.find('\n', line);
    next = newline == std::string::npos ? text.size() : newline + 1;
    size_t i = skipBlanks(line);
    if (i >= text.size() || text[i] != '#') continue;
    size_t directive = i;
    i = skipBlanks(i + 1);
    if (text.compare(i, 7, "version") != 0) continue;
    i += 7;
    size_t digits = skipBlanks(i);
    if (digits == i || digits >= text.size() || !std::isdigit(static_cast<unsigned char>(text[digits]))) continue;
    size_t end = digits;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    v.version = std::stoi(text.substr(digits, end - digits));
    size_t profile = skipBlanks(end);
    for (const char* word : {"es", "core", "compatibility"}) {
      size_t n = std::strlen(word);
      if (text.compare(profile, n, word) == 0 && (profile + n == text.size() || !isIdentifierChar(text[profile + n]))) {
        v.es = std::string(word) == "es";
        end = profile + n;
        break;
      }
    }
    v.begin = directive;
    v.end = end;
    break;
  }
  if (v.version == 100) v.es = true;
  return v;
}

namespace {

// Whether `text` contains `name` as a whole identifier followed by `(` (a function definition or
// call): how the HLSL entry point is found.
bool mentionsFunction(const std::string& text, const std::string& name) {
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    if (at > 0 && isIdentifierChar(text[at - 1])) continue;
    size_t i = at + name.size();
    if (i < text.size() && isIdentifierChar(text[i])) continue;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i < text.size() && text[i] == '(') return true;
  }
  return false;
}

std::string buildPreamble(const std::vector<std::string>& defines, bool glsl) {
  std::string preamble;
  if (glsl) preamble += "#extension GL_GOOGLE_include_directive : enable\n";
  for (const auto& d : defines) {
    auto eq = d.find('=');
    if (eq == std::string::npos)
      preamble += "#define " + d + " 1\n";
    else
      preamble += "#define " + d.substr(0, eq) + " " + d.substr(eq + 1) + "\n";
  }
  return preamble;
}

void recordExplicitQualifiers(const glslang::TIntermediate& intermediate, SourceInfo& info) {
  auto* root = intermediate.getTreeRoot() ? intermediate.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) return;
  for (auto* node : root->getSequence()) {
    auto* agg = node->getAsAggregate();
    if (!agg || agg->getOp() != glslang::EOpLinkerObjects) continue;
    for (auto* object : agg->getSequence()) {
      auto* symbol = object->getAsSymbolNode();
      if (!symbol) continue;
      const auto& type = symbol->getType();
      const auto& q = type.getQualifier();
      std::vector<std::string> keys = {symbol->getName().c_str()};
      if (type.getBasicType() == glslang::EbtBlock) keys.push_back(type.getTypeName().c_str());
      for (const auto& key : keys) {
        if (q.hasLocation()) info.explicitLocation.insert(key);
        if (q.hasBinding()) info.explicitBinding.insert(key);
        if (q.hasSet()) info.explicitSet.insert(key);
      }
    }
  }
}

struct Attempt {
  bool ok = false;
  std::vector<uint32_t> spirv;
  Diagnostics diags;
  SourceInfo info;
  std::vector<std::string> included;
};

// How glslang reads a shader: Vulkan or OpenGL rules, each producing SPIR-V, or (for checking
// emitted OpenGL GLSL/ESSL as a driver would) the dialect's own rules without SPIR-V.
enum class Client { Vulkan, OpenGL, AstOnly };

// Sets the input language, client and target environment of `shader`; returns the messages to
// parse and link with. HLSL always goes through Vulkan rules (descriptor sets, registers).
int configureEnvironment(glslang::TShader& shader, Stage stage, SourceLanguage language, Client client,
                         const std::string& entry) {
  EShLanguage lang = toGlslang(stage);
  if (language == SourceLanguage::Glsl && client == Client::AstOnly) return EShMsgDefault;
  int messages = EShMsgSpvRules;
  if (language == SourceLanguage::Hlsl) {
    shader.setEnvInput(glslang::EShSourceHlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTargetHlslFunctionality1();  // keeps semantic strings (UserSemantic decorations)
    shader.setHlslIoMapping(true);
    shader.setEntryPoint(entry.c_str());
    shader.setSourceEntryPoint(entry.c_str());
    messages |= EShMsgReadHlsl | EShMsgVulkanRules | EShMsgHlslOffsets;
  } else if (client == Client::Vulkan) {
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    messages |= EShMsgVulkanRules;
  } else {
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  }
  // Mesh and task shaders exist only from SPIR-V 1.4 / Vulkan 1.3 on.
  if (stage == Stage::Mesh || stage == Stage::Task) {
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_4);
  } else {
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  }
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  return messages;
}

Attempt compileGlslangOnce(const SourceFile& input, const std::string& text, Stage stage, SourceLanguage language,
                           Client client, const std::string& entry, const TranspileOptions& options) {
  Attempt attempt;
  EShLanguage lang = toGlslang(stage);
  glslang::TShader shader(lang);
  const char* strings[] = {text.c_str()};
  const int lengths[] = {static_cast<int>(text.size())};
  const char* names[] = {input.path.c_str()};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  std::string preamble = buildPreamble(options.defines, language == SourceLanguage::Glsl);
  shader.setPreamble(preamble.c_str());
  int messages = configureEnvironment(shader, stage, language, client, entry);

  RestrictedIncluder includer(input.path, options.includeDirs);
  bool parsed = shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages), includer);
  std::vector<std::pair<std::string, std::string>> sources = {{input.path, input.contents}};
  for (const auto& s : includer.sources()) sources.push_back(s);
  attempt.included = includer.includedFiles();
  if (!parsed) {
    parseGlslangLog(shader.getInfoLog(), input.path, sources, attempt.diags);
    if (!attempt.diags.hasErrors()) attempt.diags.error(input.path, "glslang could not parse the shader");
    return attempt;
  }
  recordExplicitQualifiers(*shader.getIntermediate(), attempt.info);

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(static_cast<EShMessages>(messages)) || !program.mapIO()) {
    parseGlslangLog(program.getInfoLog(), input.path, sources, attempt.diags);
    if (!attempt.diags.hasErrors()) attempt.diags.error(input.path, "glslang could not link the shader");
    return attempt;
  }
  glslang::SpvOptions spvOptions;
  spvOptions.generateDebugInfo = false;
  spvOptions.disableOptimizer = true;
  spvOptions.validate = false;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(lang), attempt.spirv, &logger, &spvOptions);
  std::string spvMessages = logger.getAllMessages();
  if (attempt.spirv.empty()) {
    attempt.diags.error(input.path, "SPIR-V generation failed: " + spvMessages);
    return attempt;
  }
  attempt.ok = true;
  return attempt;
}

// HLSL entry point: -e, else `main`, else the stage-conventional name found in the source.
std::string chooseHlslEntry(const std::string& text, Stage stage, const std::string& requested) {
  if (!requested.empty()) return requested;
  auto defines = [&](const std::string& name) {
    return mentionsFunction(text, name);
  };
  if (defines("main")) return "main";
  const char* conventional = nullptr;
  switch (stage) {
    case Stage::Vertex: conventional = "VSMain"; break;
    case Stage::Fragment: conventional = "PSMain"; break;
    case Stage::Geometry: conventional = "GSMain"; break;
    case Stage::TessControl: conventional = "HSMain"; break;
    case Stage::TessEvaluation: conventional = "DSMain"; break;
    case Stage::Compute: conventional = "CSMain"; break;
    case Stage::Mesh: conventional = "MSMain"; break;
    case Stage::Task: conventional = "ASMain"; break;
    default: break;
  }
  if (conventional && defines(conventional)) return conventional;
  return "main";
}

}  // namespace

FrontEndResult compileToSpirv(const SourceFile& input, const TranspileOptions& options, Diagnostics& diags) {
  FrontEndResult result;
  ensureGlslangInitialized();

  std::optional<Stage> stage = options.stage ? options.stage : stageFromPath(input.path);
  if (!stage) {
    diags.error(input.path, "cannot tell the shader stage from the file name; use -S <stage> "
                            "(vert, tesc, tese, geom, frag, comp, mesh, task)");
    return result;
  }
  // -x, else the file name's language extension, else the text (HLSL kept in `name.vert` files).
  LanguageDecision decided = decideLanguage(input.path, input.contents, options.language);
  SourceLanguage language = decided.language;
  result.info.language = language;
  result.info.languageSource = decided.source;
  result.info.languageReason = decided.reason;

  if (language == SourceLanguage::Hlsl) {
    std::string entry = chooseHlslEntry(input.contents, *stage, options.entryPoint);
    if (!mentionsFunction(input.contents, entry)) {
      diags.error(input.path, "entry point '" + entry + "' not found" +
                                  (options.entryPoint.empty() ? "; name it with -e <function>" : ""));
      return result;
    }
    Attempt a = compileGlslangOnce(input, input.contents, *stage, language, Client::Vulkan, entry, options);
    diags.append(a.diags);
    if (!a.ok) return result;
    result.ok = true;
    result.spirv = std::move(a.spirv);
    result.info = std::move(a.info);
    result.info.language = language;
    result.info.languageSource = decided.source;
    result.info.languageReason = decided.reason;
    result.info.stage = *stage;
    result.info.entryPoint = entry;
    result.info.vulkan = true;
    result.includedFiles = std::move(a.included);
    return result;
  }

  // GLSL: decide the client from the #version line. Desktop >= 400 and ES >= 310 may be Vulkan GLSL
  // (tried first) or OpenGL GLSL with loose uniforms (the fallback). Older dialects are OpenGL.
  VersionLine v = findVersion(input.contents);
  std::string text = input.contents;
  bool raised = false;
  if (v.es && v.version < 310) {
    if (v.version == 100) {
      diags.error(input.path, 1, 1,
                  "ESSL 100 is not supported yet: glslang 12 cannot make SPIR-V from `attribute`/`varying` "
                  "shaders (convert to ESSL 300, or use --target with a GLSL 300 es source)");
      return result;
    }
    // glslang 12 refuses ES < 310 for SPIR-V; parse as 310 (same line count) and emit the original.
    if (v.begin != std::string::npos) text.replace(v.begin, v.end - v.begin, "#version 310 es");
    raised = true;
  }
  std::vector<Client> clients;
  bool mayBeVulkan = (!v.es && v.version >= 400) || (v.es && v.version >= 310);
  if (mayBeVulkan) clients.push_back(Client::Vulkan);
  clients.push_back(Client::OpenGL);

  std::optional<Attempt> best;
  for (Client client : clients) {
    Attempt a = compileGlslangOnce(input, text, *stage, language, client, "main", options);
    if (a.ok) {
      a.info.vulkan = client == Client::Vulkan;
      best = std::move(a);
      break;
    }
    if (!best || a.diags.errorCount() < best->diags.errorCount()) best = std::move(a);
  }
  if (!best->ok) {
    diags.append(best->diags);
    if (decided.source == LanguageSource::Content && v.begin == std::string::npos)
      diags.note(input.path, "parsed as GLSL (" + decided.reason + "); if this is HLSL, say so with -x hlsl");
    return result;
  }
  diags.append(best->diags);  // warnings
  result.ok = true;
  result.spirv = std::move(best->spirv);
  result.info = std::move(best->info);
  result.info.language = language;
  result.info.languageSource = decided.source;
  result.info.languageReason = decided.reason;
  result.info.stage = *stage;
  result.info.version = v.version;
  result.info.es = v.es;
  result.info.versionRaised = raised;
  result.info.entryPoint = "main";
  result.includedFiles = std::move(best->included);
  return result;
}

bool verifyCompiles(const std::string& text, SourceLanguage language, Stage stage, const std::string& entryPoint,
                    bool vulkanSemantics, const std::string& displayName, Diagnostics& diags) {
  ensureGlslangInitialized();
  glslang::TShader shader(toGlslang(stage));
  const char* strings[] = {text.c_str()};
  const char* names[] = {displayName.c_str()};
  const int lengths[] = {static_cast<int>(text.size())};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  int messages = configureEnvironment(shader, stage, language, vulkanSemantics ? Client::Vulkan : Client::AstOnly,
                                      entryPoint);
  // OpenGL GLSL/ESSL is checked as the driver would see it: AST only, the original dialect's rules.
  glslang::TShader::ForbidIncluder noIncludes;
  bool ok = shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages), noIncludes);
  if (ok) {
    glslang::TProgram program;
    program.addShader(&shader);
    ok = program.link(static_cast<EShMessages>(messages));
    if (!ok) parseGlslangLog(program.getInfoLog(), displayName, {{displayName, text}}, diags);
  } else {
    parseGlslangLog(shader.getInfoLog(), displayName, {{displayName, text}}, diags);
  }
  if (!ok && !diags.hasErrors()) diags.error(displayName, "emitted shader does not compile");
  return ok;
}

}  // namespace stereoshift
