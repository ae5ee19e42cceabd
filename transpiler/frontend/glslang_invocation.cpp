// One glslang run (see glslang_invocation.h): the environment it parses with, the includes it may
// read, the limits its tree must keep, and the SPIR-V it makes.
#include "transpiler/frontend/glslang_invocation.h"

#include "core/crash_phase.h"
#include "transpiler/frontend/glslang_log.h"
#include "transpiler/frontend/include_resolver.h"
#include "transpiler/frontend/source_limits.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <optional>

namespace stereoshift {

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

namespace {

// N of `layout(num_views = N) in;` (GL_OVR_multiview), 0 when the text declares none. glslang keeps the
// count in its parse context only, so the text is read again, through the lexer (`num_views = N`
// in a comment is none).
int declaredViewCount(const std::string& text) {
  source::Lexer lexer(text);
  source::Token t, name, equals;  // the two tokens before `t`, comments left out
  bool seen[2] = {false, false};
  while (lexer.next(t)) {
    if (t.kind == source::TokenKind::Comment) continue;
    bool count = seen[0] && seen[1] && t.kind == source::TokenKind::Number &&
                 equals.kind == source::TokenKind::Punctuation && text[equals.begin] == '=' &&
                 name.kind == source::TokenKind::Identifier && source::tokenText(text, name) == "num_views";
    if (count) {
      std::string digits = source::spelledString(text, t);
      int views = 0;
      for (size_t i = 0; i < digits.size() && isDecimalDigit(digits[i]) && views < 1000; ++i)
        views = views * 10 + (digits[i] - '0');
      if (views > 0) return views;
    }
    name = equals;
    equals = t;
    seen[0] = seen[1];
    seen[1] = true;
  }
  return 0;
}

// The linker objects of `intermediate` (its global variables and blocks), in order, to `visit`;
// stops when `visit` returns false.
void forEachLinkerObject(const glslang::TIntermediate& intermediate,
                         const std::function<bool(const glslang::TIntermSymbol&)>& visit) {
  auto* root = intermediate.getTreeRoot() ? intermediate.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) return;
  for (auto* node : root->getSequence()) {
    auto* agg = node->getAsAggregate();
    if (!agg || agg->getOp() != glslang::EOpLinkerObjects) continue;
    for (auto* object : agg->getSequence())
      if (auto* symbol = object->getAsSymbolNode(); symbol && !visit(*symbol)) return;
  }
}

void recordExplicitQualifiers(const glslang::TIntermediate& intermediate, SourceInfo& info) {
  forEachLinkerObject(intermediate, [&](const glslang::TIntermSymbol& symbol) {
    const auto& type = symbol.getType();
    const auto& q = type.getQualifier();
    std::vector<std::string> keys = {symbol.getName().c_str()};
    if (type.getBasicType() == glslang::EbtBlock) keys.push_back(type.getTypeName().c_str());
    for (const auto& key : keys) {
      if (q.hasLocation()) info.explicitLocation.insert(key);
      if (q.hasBinding()) info.explicitBinding.insert(key);
    }
    return true;
  });
}

// The first user interface variable of `intermediate` written the OpenGL way (Attempt::openGLStyleInterface).
std::string firstOpenGLStyleInterface(const glslang::TIntermediate& intermediate) {
  std::string found;
  forEachLinkerObject(intermediate, [&](const glslang::TIntermSymbol& symbol) {
    const auto& type = symbol.getType();
    const auto& q = type.getQualifier();
    const bool block = type.getBasicType() == glslang::EbtBlock;
    std::string name = block ? type.getTypeName().c_str() : symbol.getName().c_str();
    if (name.starts_with("gl_") || q.builtIn != glslang::EbvNone || q.layoutPushConstant) return true;
    const bool inOut = q.storage == glslang::EvqVaryingIn || q.storage == glslang::EvqVaryingOut;
    const bool resource =
        q.storage == glslang::EvqBuffer || (q.storage == glslang::EvqUniform && (block || type.isOpaque()));
    if (inOut && !q.hasLocation())
      found = std::string(q.storage == glslang::EvqVaryingIn ? "input" : "output") + " '" + name + "' has no location";
    else if (resource && !q.hasBinding())
      found = std::string(block ? "block" : "uniform") + " '" + name + "' has no binding";
    return found.empty();
  });
  return found;
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
      message = controlFlowNestingMessage();
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

}  // namespace

int configureEnvironment(glslang::TShader& shader, Stage stage, SourceLanguage language, Client client,
                         const std::string& entry, const FrontEndOptions* options) {
  EShLanguage lang = toGlslang(stage);
  // GLSL with another entry function (-e / --source-entrypoint): glslang compiles it as `main`.
  if (language == SourceLanguage::Glsl && !entry.empty() && entry != "main") {
    shader.setEntryPoint("main");
    shader.setSourceEntryPoint(entry.c_str());
  }
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
                           Client client, const std::string& entry, const FrontEndOptions& options) {
  Attempt attempt;
  ScopedCrashPhase phase(language == SourceLanguage::Hlsl ? kGlslangHlslPhase : kGlslangGlslPhase);
  EShLanguage lang = toGlslang(stage);
  glslang::TShader shader(lang);
  // glslang ends its input at a NUL byte, even in a comment: the compiler's copy has spaces there.
  const std::string given = source::blankNuls(text);
  const char* strings[] = {given.c_str()};
  const int lengths[] = {static_cast<int>(given.size())};
  const char* names[] = {input.path.c_str()};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  std::string preamble = buildPreamble(options.defines, language == SourceLanguage::Glsl);
  for (const auto& extension : options.analysisExtensions) preamble += "#extension " + extension + " : enable\n";
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
  if (language == SourceLanguage::Glsl && client == Client::Vulkan)
    attempt.openGLStyleInterface = firstOpenGLStyleInterface(*shader.getIntermediate());
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
  spvOptions.generateDebugInfo = options.sourceLines && language == SourceLanguage::Hlsl && stage == Stage::Fragment;
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

}  // namespace stereoshift
