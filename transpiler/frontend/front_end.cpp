#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/glslang_log.h"
#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/frontend/source_limits.h"
#include "transpiler/frontend/language_detect.h"
#include "transpiler/frontend/legacy_glsl.h"
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
    case Stage::RayGen: return EShLangRayGen;
    case Stage::Intersection: return EShLangIntersect;
    case Stage::AnyHit: return EShLangAnyHit;
    case Stage::ClosestHit: return EShLangClosestHit;
    case Stage::Miss: return EShLangMiss;
    case Stage::Callable: return EShLangCallable;
    default: return EShLangVertex;
  }
}

// Why an #include was refused: the error to report in place of glslang's "Could not process
// include directive" at the directive, or (`ownLocation`) a located error inside the included file.
struct IncludeRefusal {
  std::string includer, header;  // the directive: the file it is in (as glslang names it) and its header
  Diagnostic replacement;
  bool ownLocation = false;
};

// Whether `text` opens (after blank lines and comments) with `#pragma once` or with
// `#ifndef NAME` then `#define NAME`: an include guard, so a nested re-inclusion adds nothing.
bool hasIncludeGuard(const std::string& text) {
  std::vector<std::string> directives;  // the first two lines that are not blank or comments
  bool inComment = false;
  for (size_t line = 0; line < text.size() && directives.size() < 2;) {
    size_t newline = text.find('\n', line);
    size_t end = newline == std::string::npos ? text.size() : newline;
    std::string code;
    for (size_t i = line; i < end; ++i) {
      if (inComment) {
        if (text.compare(i, 2, "*/") == 0) inComment = false, ++i;
      } else if (text.compare(i, 2, "/*") == 0) {
        inComment = true, ++i;
      } else if (text.compare(i, 2, "//") == 0) {
        break;
      } else {
        code += text[i];
      }
    }
    std::istringstream words(code);
    std::string word, joined;
    while (words >> word) joined += (joined.empty() ? "" : " ") + word;
    if (!joined.empty()) directives.push_back(joined);
    line = end + 1;
  }
  if (!directives.empty() && (directives[0] == "#pragma once" || directives[0] == "# pragma once")) return true;
  if (directives.size() < 2 || !directives[0].starts_with("#ifndef ") || !directives[1].starts_with("#define ")) return false;
  std::string guard = directives[0].substr(8);
  return directives[1] == "#define " + guard || directives[1].starts_with("#define " + guard + " ");
}

// Resolves #include only inside the including file's directory and the -I directories, so a
// shader tree conversion never reads outside what the user named. It also refuses what would make
// glslang run away: an include cycle without include guards (glslang would include forever),
// nesting deeper than kMaxIncludeDepth, more than kMaxSourceBytes of source in all, and an
// included file past the bracket limit (source_limits.h).
class RestrictedIncluder : public glslang::TShader::Includer {
 public:
  RestrictedIncluder(std::string mainFile, std::vector<std::string> includeDirs, size_t mainBytes)
      : mainFile_(std::move(mainFile)), includeDirs_(std::move(includeDirs)), totalBytes_(mainBytes) {
    std::error_code ec;
    chain_.push_back({mainFile_, fs::weakly_canonical(mainFile_, ec)});
  }

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    if (!beginDirective(header, includer, depth)) return nullptr;
    fs::path base = (depth <= 1 || !includer || !*includer) ? fs::path(mainFile_).parent_path()
                                                            : fs::path(includer).parent_path();
    if (auto* r = tryOpen(base, header)) return r;
    if (refusedThisDirective_) return nullptr;
    return searchIncludeDirs(header);
  }

  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    // glslang asks here too after includeLocal found nothing; a refusal there stands.
    if (refusedThisDirective_ && currentHeader_ == header && currentIncluder_ == (includer ? includer : "") &&
        currentDepth_ == depth)
      return nullptr;
    if (!beginDirective(header, includer, depth)) return nullptr;
    return searchIncludeDirs(header);
  }

  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

  const std::vector<std::pair<std::string, std::string>>& sources() const { return sources_; }
  const std::vector<std::string>& includedFiles() const { return included_; }
  const std::vector<IncludeRefusal>& refusals() const { return refusals_; }

 private:
  struct OpenFile {
    std::string name;  // as diagnostics name it
    fs::path identity;
    bool guarded = false;  // opens with an include guard or #pragma once
  };

  // Starts resolving one directive: `depth` files are open once it succeeds (glslang counts the
  // shader itself as 0), so the include stack is the first `depth` entries of chain_.
  bool beginDirective(const char* header, const char* includer, size_t depth) {
    currentHeader_ = header;
    currentIncluder_ = includer ? includer : "";
    currentDepth_ = depth;
    refusedThisDirective_ = false;
    if (chain_.size() > depth) chain_.resize(depth);
    if (depth > kMaxIncludeDepth) {
      refuse("#include nests deeper than " + std::to_string(kMaxIncludeDepth) + " files (the front end's limit)");
      return false;
    }
    return true;
  }

  IncludeResult* searchIncludeDirs(const char* header) {
    for (const auto& dir : includeDirs_) {
      if (auto* r = tryOpen(dir, header)) return r;
      if (refusedThisDirective_) return nullptr;
    }
    return nullptr;
  }

  void refuse(std::string message) {
    IncludeRefusal r;
    r.includer = currentIncluder_;
    r.header = currentHeader_;
    r.replacement.message = std::move(message);
    refusals_.push_back(std::move(r));
    refusedThisDirective_ = true;
  }

  IncludeResult* tryOpen(const fs::path& dir, const char* header) {
    fs::path candidate = (dir.empty() ? fs::path(".") : dir) / header;
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) return nullptr;
    fs::path root = fs::weakly_canonical(dir.empty() ? fs::path(".") : dir, ec);
    fs::path resolved = fs::weakly_canonical(candidate, ec);
    auto rel = resolved.lexically_relative(root);
    // A build sandbox (Bazel's) lays declared inputs out as symbolic links to the real files: a file
    // inside the directory as named is inside it, wherever its link points.
    auto named = candidate.lexically_normal().lexically_relative((dir.empty() ? fs::path(".") : dir).lexically_normal());
    auto escapes = [](const fs::path& r) { return r.empty() || *r.begin() == ".."; };
    if (escapes(rel) && escapes(named)) return nullptr;  // escapes the allowed directory
    std::string name = candidate.lexically_normal().string();

    // A file that is already open: with an include guard (or #pragma once) its inner copy would
    // be skipped anyway, so it is included as empty text; without one nothing ends the recursion.
    auto open = std::find_if(chain_.begin(), chain_.end(), [&](const OpenFile& f) { return f.identity == resolved; });
    if (open != chain_.end()) {
      if (!open->guarded) {
        refuse("#include cycle: " + describeCycle(resolved, name));
        return nullptr;
      }
      chain_.push_back({name, resolved, true});
      return new IncludeResult(name, "", 0, new std::string);
    }
    uintmax_t bytes = fs::file_size(candidate, ec);
    if (ec || bytes > kMaxSourceBytes - std::min(totalBytes_, kMaxSourceBytes)) {
      refuse("including " + name + " takes the shader's source past " + describeBytes(kMaxSourceBytes) +
             " (the front end's limit)");
      return nullptr;
    }
    auto* text = new std::string;
    if (!readFile(candidate.string(), text)) {
      delete text;
      return nullptr;
    }
    totalBytes_ += text->size();
    if (auto violation = findNestingViolation(*text)) {
      refuse(violation->message);
      refusals_.back().replacement.file = name;
      refusals_.back().replacement.line = violation->line;
      refusals_.back().replacement.column = violation->column;
      refusals_.back().ownLocation = true;
      delete text;
      return nullptr;
    }
    sources_.emplace_back(name, *text);
    if (std::find(included_.begin(), included_.end(), name) == included_.end()) included_.push_back(name);
    chain_.push_back({name, resolved, hasIncludeGuard(*text)});
    return new IncludeResult(name, text->data(), text->size(), text);
  }

  // "a.vert -> x.glsl -> x.glsl": the include stack from the shader up to the first file that
  // repeats, with `next` (about to be opened) last.
  std::string describeCycle(const fs::path& nextIdentity, const std::string& nextName) const {
    std::vector<OpenFile> path = chain_;
    path.push_back({nextName, nextIdentity});
    std::string text;
    for (size_t k = 0; k < path.size(); ++k) {
      text += (k ? " -> " : "") + path[k].name;
      bool repeats = std::any_of(path.begin(), path.begin() + static_cast<long>(k),
                                 [&](const OpenFile& f) { return f.identity == path[k].identity; });
      if (repeats) break;
    }
    return text;
  }

  std::string mainFile_;
  std::vector<std::string> includeDirs_;
  size_t totalBytes_ = 0;
  std::vector<OpenFile> chain_;  // the shader, then the include stack
  std::string currentHeader_, currentIncluder_;
  size_t currentDepth_ = 0;
  bool refusedThisDirective_ = false;
  std::vector<IncludeRefusal> refusals_;
  std::vector<std::pair<std::string, std::string>> sources_;
  std::vector<std::string> included_;
};

// glslang's errors with each refused #include's "Could not process include directive" replaced by
// the reason it was refused.
Diagnostics explainRefusedIncludes(const Diagnostics& raw, const std::vector<IncludeRefusal>& refusals) {
  static constexpr std::string_view kCouldNotInclude = "'#include' : Could not process include directive for header name: ";
  Diagnostics out;
  for (Diagnostic d : raw.all()) {
    if (d.message.starts_with(kCouldNotInclude)) {
      std::string header = d.message.substr(kCouldNotInclude.size());
      for (const auto& r : refusals) {
        if (r.header != header || (!r.includer.empty() && r.includer != d.file)) continue;
        if (r.ownLocation) {
          d = r.replacement;
        } else {
          d.message = r.replacement.message;
        }
        break;
      }
    }
    out.add(std::move(d));
  }
  return out;
}

}  // namespace

namespace {

// The versions a `#version` line may name (GLSL 1.10-4.60, ESSL 1.00-3.20).
bool isGlslVersion(long long n) {
  for (int known : {100, 110, 120, 130, 140, 150, 300, 310, 320, 330, 400, 410, 420, 430, 440, 450, 460})
    if (n == known) return true;
  return false;
}

}  // namespace

// A hand-written scan: a std::regex over the whole text cost more than the rest of the front end's
// reading of the source. It never throws: the build parent runs it on every shader of a tree.
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
    if (text.compare(i, 7, "version") != 0 || (i + 7 < text.size() && isIdentifierChar(text[i + 7]))) continue;
    i += 7;
    size_t digits = skipBlanks(i);
    size_t end = digits;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    v.begin = directive;
    v.end = end;
    if (end == digits || (end < text.size() && isIdentifierChar(text[end]))) {
      // `#version 3x0`, `#version es`, a bare `#version`: quote the directive as written.
      size_t quoteEnd = digits;
      while (quoteEnd < text.size() && !std::isspace(static_cast<unsigned char>(text[quoteEnd])) &&
             text.compare(quoteEnd, 2, "//") != 0 && text.compare(quoteEnd, 2, "/*") != 0)
        ++quoteEnd;
      std::string quoted = text.substr(directive, std::min<size_t>(quoteEnd - directive, 48));
      v.version = 0;
      v.problem = "'" + quoted + "': not a GLSL version";
      v.problemAt = directive;
      break;
    }
    // At most 9 digits are read as a number, so the conversion cannot overflow an int.
    long long number = 0;
    for (size_t k = digits; k < end && k - digits < 10; ++k) number = number * 10 + (text[k] - '0');
    if (end - digits > 9 || !isGlslVersion(number)) {
      std::string written = text.substr(digits, std::min<size_t>(end - digits, 24));
      if (end - digits > 24) written += "...";
      v.version = 0;
      v.problem = "#version " + written + " is not a GLSL version";
      v.problemAt = digits;
      break;
    }
    v.version = static_cast<int>(number);
    size_t profile = skipBlanks(end);
    for (const char* word : {"es", "core", "compatibility"}) {
      size_t n = std::strlen(word);
      if (text.compare(profile, n, word) == 0 && (profile + n == text.size() || !isIdentifierChar(text[profile + n]))) {
        v.es = std::string(word) == "es";
        v.end = profile + n;
        break;
      }
    }
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

// N of `layout(num_views = N) in;` (GL_OVR_multiview), 0 when the text declares none. glslang keeps the
// count in its parse context only, so the text is read again (a mention in a comment is harmless: it
// only matters for a shader that reads the view index).
int declaredViewCount(std::string_view text) {
  for (size_t at = text.find("num_views"); at != std::string_view::npos; at = text.find("num_views", at + 1)) {
    size_t i = at + 9;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size() || text[i] != '=') continue;
    ++i;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    int views = 0;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && views < 1000)
      views = views * 10 + (text[i++] - '0');
    if (views > 0) return views;
  }
  return 0;
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
      }
    }
  }
}

// The first node of glslang's tree past kMaxSyntaxTreeDepth levels or kMaxControlFlowNesting
// nested if / ?: / loop / switch, as a located error. The walk keeps its own stack: the tree is
// exactly what may be too deep for recursion.
std::optional<Diagnostic> findTreeLimitViolation(TIntermNode* root, const std::string& mainFile) {
  struct Pending {
    TIntermNode* node;
    int depth, controlNesting;
    TIntermNode* statement;  // the statement the node is part of: where a too deep tree is reported
  };
  std::vector<Pending> stack;
  if (root) stack.push_back({root, 1, 0, root});
  while (!stack.empty()) {
    // Plain variables, not structured bindings: the lambda below captures them (clang 14 cannot).
    const Pending top = stack.back();
    stack.pop_back();
    TIntermNode* node = top.node;
    int depth = top.depth, controlNesting = top.controlNesting;
    TIntermNode* statement = top.statement;
    bool control = node->getAsSelectionNode() || node->getAsLoopNode() || node->getAsSwitchNode();
    controlNesting += control ? 1 : 0;
    std::string message;
    TIntermNode* reported = node;
    if (control && controlNesting > kMaxControlFlowNesting) {
      message = "control flow (if, ?:, loops, switch) nests deeper than " + std::to_string(kMaxControlFlowNesting) +
                " levels here (the front end's limit: SPIR-V validation time grows with the cube of it)";
    } else if (depth > kMaxSyntaxTreeDepth) {
      message = "this statement nests deeper than " + std::to_string(kMaxSyntaxTreeDepth) +
                " levels of syntax tree (the front end's limit: glslang walks the tree by recursion)";
      reported = statement;
    }
    if (!message.empty()) {
      const glslang::TSourceLoc& loc = reported->getLoc();
      const char* file = loc.getFilename();
      return Diagnostic{Severity::Error, file && *file ? file : mainFile, std::max(loc.line, 1),
                        std::max(loc.column, 1), message};
    }
    auto push = [&](TIntermNode* child) {
      if (child) stack.push_back({child, depth + 1, controlNesting, statement});
    };
    if (auto* aggregate = node->getAsAggregate()) {
      bool statements = aggregate->getOp() == glslang::EOpSequence;
      for (auto* child : aggregate->getSequence())
        if (child) stack.push_back({child, depth + 1, controlNesting, statements ? child : statement});
    } else if (auto* binary = node->getAsBinaryNode()) {
      push(binary->getLeft());
      push(binary->getRight());
    } else if (auto* unary = node->getAsUnaryNode()) {
      push(unary->getOperand());
    } else if (auto* selection = node->getAsSelectionNode()) {
      push(selection->getCondition());
      push(selection->getTrueBlock());
      push(selection->getFalseBlock());
    } else if (auto* loop = node->getAsLoopNode()) {
      push(loop->getTest());
      push(loop->getTerminal());
      push(loop->getBody());
    } else if (auto* switchNode = node->getAsSwitchNode()) {
      push(switchNode->getCondition());
      push(switchNode->getBody());
    } else if (auto* branch = node->getAsBranchNode()) {
      push(branch->getExpression());
    }
  }
  return std::nullopt;
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

// The glslang client version and SPIR-V version of an environment (glslc's defaults: Vulkan 1.1
// makes SPIR-V 1.3, 1.2 makes 1.5, 1.3 makes 1.6); --target-spv overrides the SPIR-V version.
glslang::EShTargetClientVersion vulkanClientVersion(TargetEnv env) {
  switch (env) {
    case TargetEnv::Vulkan1_1: return glslang::EShTargetVulkan_1_1;
    case TargetEnv::Vulkan1_2: return glslang::EShTargetVulkan_1_2;
    case TargetEnv::Vulkan1_3: return glslang::EShTargetVulkan_1_3;
    default: return glslang::EShTargetVulkan_1_0;
  }
}

glslang::EShTargetLanguageVersion spirvVersion(int minor) {
  static const glslang::EShTargetLanguageVersion versions[] = {
      glslang::EShTargetSpv_1_0, glslang::EShTargetSpv_1_1, glslang::EShTargetSpv_1_2, glslang::EShTargetSpv_1_3,
      glslang::EShTargetSpv_1_4, glslang::EShTargetSpv_1_5, glslang::EShTargetSpv_1_6};
  return versions[std::clamp(minor, 0, 6)];
}

int defaultSpirvMinor(TargetEnv env) {
  switch (env) {
    case TargetEnv::Vulkan1_1: return 3;
    case TargetEnv::Vulkan1_2: return 5;
    case TargetEnv::Vulkan1_3: return 6;
    default: return 0;
  }
}

// Sets the input language, client and target environment of `shader`; returns the messages to
// parse and link with. HLSL always goes through Vulkan rules (descriptor sets, registers).
// `options` (absent when checking emitted text) carries --target-env and --target-spv.
int configureEnvironment(glslang::TShader& shader, Stage stage, SourceLanguage language, Client client,
                         const std::string& entry, const TranspileOptions* options = nullptr) {
  EShLanguage lang = toGlslang(stage);
  if (language == SourceLanguage::Glsl && client == Client::AstOnly) return EShMsgDefault;
  // An OpenGL environment has no Vulkan version: HLSL (always Vulkan rules) then keeps 1.0.
  std::optional<TargetEnv> env = options ? options->targetEnv : std::nullopt;
  glslang::EShTargetClientVersion vulkanVersion =
      env && *env != TargetEnv::OpenGL45 ? vulkanClientVersion(*env) : glslang::EShTargetVulkan_1_0;
  int messages = EShMsgSpvRules;
  if (language == SourceLanguage::Hlsl) {
    shader.setEnvInput(glslang::EShSourceHlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, vulkanVersion);
    shader.setEnvTargetHlslFunctionality1();  // keeps semantic strings (UserSemantic decorations)
    shader.setHlslIoMapping(true);
    shader.setEntryPoint(entry.c_str());
    shader.setSourceEntryPoint(entry.c_str());
    messages |= EShMsgReadHlsl | EShMsgVulkanRules | EShMsgHlslOffsets;
  } else if (client == Client::Vulkan) {
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, vulkanVersion);
    messages |= EShMsgVulkanRules;
  } else {
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  }
  // OpenGL rules take SPIR-V 1.0 only (ARB_gl_spirv): a Vulkan environment sets the version of the
  // Vulkan attempt, and an OpenGL GLSL shader of the same run keeps 1.0.
  const bool openGLRules = language == SourceLanguage::Glsl && client == Client::OpenGL;
  int spirvMinor = openGLRules ? 0 : options && options->targetSpv ? *options->targetSpv : env ? defaultSpirvMinor(*env) : 0;
  // Mesh and task shaders exist only from SPIR-V 1.4 / Vulkan 1.3 on, ray-tracing ones from SPIR-V 1.4
  // / Vulkan 1.2 on.
  if (stage == Stage::Mesh || stage == Stage::Task) {
    if (!env || *env != TargetEnv::Vulkan1_3) shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
    spirvMinor = std::max(spirvMinor, 4);
  } else if (isRayTracing(stage)) {
    if (!env || (*env != TargetEnv::Vulkan1_2 && *env != TargetEnv::Vulkan1_3))
      shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    spirvMinor = std::max(spirvMinor, 4);
  }
  shader.setEnvTarget(glslang::EShTargetSpv, spirvVersion(spirvMinor));
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
  int messages = configureEnvironment(shader, stage, language, client, entry, &options);

  RestrictedIncluder includer(input.path, includeSearchPath(input.path, options.includeDirs), text.size());
  bool parsed = shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages), includer);
  std::vector<std::pair<std::string, std::string>> sources = {{input.path, input.contents}};
  for (const auto& s : includer.sources()) sources.push_back(s);
  attempt.included = includer.includedFiles();
  if (!parsed) {
    Diagnostics raw;
    parseGlslangLog(shader.getInfoLog(), input.path, sources, raw);
    attempt.diags = explainRefusedIncludes(raw, includer.refusals());
    if (!attempt.diags.hasErrors()) attempt.diags.error(input.path, "glslang could not parse the shader");
    return attempt;
  }
  if (auto violation = findTreeLimitViolation(shader.getIntermediate()->getTreeRoot(), input.path)) {
    attempt.diags.add(*violation);
    return attempt;
  }
  recordExplicitQualifiers(*shader.getIntermediate(), attempt.info);
  attempt.info.multiviewViews = declaredViewCount(text);

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(static_cast<EShMessages>(messages)) || !program.mapIO()) {
    parseGlslangLog(program.getInfoLog(), input.path, sources, attempt.diags);
    if (!attempt.diags.hasErrors()) attempt.diags.error(input.path, "glslang could not link the shader");
    return attempt;
  }
  // glslang links an HLSL shader whose entry point is missing, with only a warning, into a module
  // without one.
  if (language == SourceLanguage::Hlsl && std::strstr(program.getInfoLog(), "Entry point not found")) {
    attempt.diags.error(input.path, "Entry point not found: '" + entry + "'");
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

// The entry-point name samples use for `stage` (VSMain, PSMain, ...), null where there is none.
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

// HLSL entry point: -e, else `main`, else the stage-conventional name found in the source.
std::string chooseHlslEntry(const std::string& text, Stage stage, const std::string& requested) {
  if (!requested.empty()) return requested;
  auto defines = [&](const std::string& name) {
    return mentionsFunction(text, name);
  };
  if (defines("main")) return "main";
  const char* conventional = conventionalHlslEntry(stage);
  if (conventional && defines(conventional)) return conventional;
  // Effect files name their entry points in their techniques: the first one of this stage.
  for (const auto& [techniqueStage, name] : techniqueEntryPoints(text)) {
    if (techniqueStage == stage && defines(name)) return name;
  }
  // Else the signature says it (`VS`, `mainVS`, `RenderSceneVS`...): the first function of the file
  // whose outputs carry this stage's system value.
  if (std::string bySignature = entryPointBySignature(text, stage); !bySignature.empty()) return bySignature;
  return "main";
}

// 1-based line and column of byte `offset` of `text`.
std::pair<int, int> lineAndColumn(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
  size_t lineStart = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  lineStart = (lineStart == std::string::npos || offset == 0) ? 0 : lineStart + 1;
  return {line, static_cast<int>(offset - lineStart) + 1};
}

// Refuses, before glslang sees it, a source past kMaxSourceBytes or past the nesting limits, each
// with where and why (glslang would take minutes or overflow its stack on such input).
bool withinSourceLimits(const SourceFile& input, Diagnostics& diags) {
  if (input.contents.size() > kMaxSourceBytes) {
    diags.error(input.path, "shader source is " + describeBytes(input.contents.size()) + "; the front end's limit is " +
                                describeBytes(kMaxSourceBytes));
    return false;
  }
  if (auto violation = findNestingViolation(input.contents)) {
    diags.error(input.path, violation->line, violation->column, violation->message);
    return false;
  }
  return true;
}

// A garbled #version, said as such: glslang itself would fall back to ESSL 100 and complain that ES
// shaders for SPIR-V need version 310, which points the wrong way. (A missing one is not a problem:
// the shader is GLSL 110 or ESSL 100, see decideLegacyDialect.)
void reportVersionProblem(const SourceFile& input, const VersionLine& v, Diagnostics& diags) {
  auto [line, column] = lineAndColumn(input.contents, v.problemAt);
  diags.error(input.path, line, column, v.problem);
}

}  // namespace

FrontEndResult compileToSpirv(const SourceFile& input, const TranspileOptions& options, Diagnostics& diags,
                              const StageDecision* stageGiven) {
  FrontEndResult result;
  ensureGlslangInitialized();
  if (!withinSourceLimits(input, diags)) return result;

  StageDecision stageDecision =
      stageGiven ? *stageGiven : decideStage(input.path, input.contents, options.stage, options.stageExtensions);
  std::optional<Stage> stage = stageDecision.stage;
  if (!stageDecision.problem.empty()) {
    diags.error(input.path, stageDecision.problemLine, stageDecision.problemColumn, stageDecision.problem);
    return result;
  }
  if (!stage) {
    diags.error(input.path, 1, 1, stageHint(input.path));
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
    // The text names its entry point, or the entry comes from an #include or a macro (`ENTRY(main)`),
    // which only glslang's preprocessor sees: then `main` and the stage's conventional name are tried
    // on the preprocessed shader (glslang links without an entry point, with a warning, when the name
    // is missing).
    std::vector<std::string> candidates = {entry};
    if (!mentionsFunction(input.contents, entry) && options.entryPoint.empty()) {
      candidates = {"main"};
      if (const char* conventional = conventionalHlslEntry(*stage)) candidates.push_back(conventional);
    }
    auto entryMissing = [](const Diagnostics& d) {
      return std::any_of(d.all().begin(), d.all().end(), [](const Diagnostic& x) {
        return x.message.find("Entry point not found") != std::string::npos;
      });
    };
    // Effect files: glslang parses the HLSL once technique and state blocks are blanked out.
    std::string blanked = blankEffectBlocks(input.contents);
    Attempt a;
    bool found = false;
    for (const auto& candidate : candidates) {
      a = compileGlslangOnce(input, blanked, *stage, language, Client::Vulkan, candidate, options);
      if (!entryMissing(a.diags)) {
        entry = candidate;
        found = true;
        break;
      }
    }
    if (!found) {
      diags.error(input.path, "entry point '" + entry + "' not found" +
                                  (options.entryPoint.empty() ? "; name it with -e <function>" : ""));
      return result;
    }
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
    // Conservative: a mention in a comment only makes the injected binding skip more numbers.
    result.info.vulkanBindings = input.contents.find("vk::binding") != std::string::npos;
    result.includedFiles = std::move(a.included);
    return result;
  }

  // GLSL: decide the client from the #version line. Desktop >= 400 and ES >= 310 may be Vulkan GLSL
  // (tried first) or OpenGL GLSL with loose uniforms (the fallback). Older dialects are OpenGL.
  VersionLine v = findVersion(input.contents);
  if (!v.problem.empty()) {
    reportVersionProblem(input, v, diags);
    return result;
  }
  std::string text = input.contents;
  // ESSL 100 and desktop 110-150 (and no #version at all): glslang makes SPIR-V only from ESSL 310 and
  // GLSL 330 on, and asked for 1xx with a SPIR-V client it fails its own built-ins and prints them to
  // stdout. Such shaders are parsed as a faithful ESSL 310 / GLSL 330 translation instead (the
  // same-language output is the original text, see glsl_splice.h), so glslang never sees 1xx here.
  LegacyDialect dialect = decideLegacyDialect(input.contents, v);
  bool usesCompatibilityBuiltIns = false;
  if (dialect.legacy) {
    LegacyTranslation translated = translateLegacyGlsl(input.contents, *stage, dialect, input.path);
    if (!translated.ok) {
      diags.add(translated.error);
      return result;
    }
    text = std::move(translated.text);
    usesCompatibilityBuiltIns = !translated.declared.empty();
    v.version = dialect.version;
    v.es = dialect.es;
    result.dialectReason = dialect.reason;
  } else if (v.es && v.version < 310) {
    // glslang 12 refuses ES < 310 for SPIR-V; parse as 310 (same line count) and emit the original.
    text.replace(v.begin, v.end - v.begin, "#version 310 es");
  }
  std::vector<Client> clients;
  bool mayBeVulkan = (!v.es && v.version >= 400) || (v.es && v.version >= 310);
  if (mayBeVulkan && options.targetEnv != TargetEnv::OpenGL45) clients.push_back(Client::Vulkan);  // --target-env opengl: GL rules only
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
  result.info.compatibilityBuiltIns = usesCompatibilityBuiltIns;
  result.info.entryPoint = "main";
  result.includedFiles = std::move(best->included);
  return result;
}

bool verifyCompiles(const std::string& text, SourceLanguage language, Stage stage, const std::string& entryPoint,
                    bool vulkanSemantics, const std::string& displayName, Diagnostics& diags,
                    const TranspileOptions* environment, const std::string& includeFrom) {
  ensureGlslangInitialized();
  glslang::TShader shader(toGlslang(stage));
  const char* strings[] = {text.c_str()};
  const char* names[] = {displayName.c_str()};
  const int lengths[] = {static_cast<int>(text.size())};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  int messages = configureEnvironment(shader, stage, language, vulkanSemantics ? Client::Vulkan : Client::AstOnly,
                                      entryPoint, environment);
  // OpenGL GLSL/ESSL is checked as the driver would see it: AST only, the original dialect's rules.
  // A text spliced into the original (`includeFrom`: the input's path) still names the input's
  // #include files and macros: they resolve as they did for the input, with the same -D and -I.
  std::string preamble;
  if (!includeFrom.empty() && environment) {
    preamble = buildPreamble(environment->defines, language == SourceLanguage::Glsl);
    shader.setPreamble(preamble.c_str());
  }
  glslang::TShader::ForbidIncluder noIncludes;
  std::optional<RestrictedIncluder> includer;
  if (!includeFrom.empty())
    includer.emplace(includeFrom, includeSearchPath(includeFrom, environment ? environment->includeDirs
                                                                            : std::vector<std::string>{}),
                     text.size());
  glslang::TShader::Includer& includes = includer ? static_cast<glslang::TShader::Includer&>(*includer) : noIncludes;
  bool parsed = shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages), includes);
  return linkParsedShader(shader, parsed, messages, displayName, text, diags);
}

bool linkParsedShader(glslang::TShader& shader, bool parsed, int messages, const std::string& displayName,
                      const std::string& text, Diagnostics& diags) {
  bool ok = parsed;
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
