// The front end (see front_end.h): this turns a shader file into SPIR-V. It decides the stage and
// the language, refuses text past the source limits, then takes the route of the language: HLSL with
// its entry point (effect blocks blanked), GLSL by its #version (ESSL 100 and GLSL 110-150 through
// their legacy translation, Vulkan GLSL tried before OpenGL GLSL). glslang itself is run by
// glslang_invocation.cpp, #include resolved by include_resolver.cpp; recompile.cpp checks output.
#include "transpiler/frontend/front_end.h"

#include "transpiler/frontend/glsl_lift.h"
#include "transpiler/frontend/glslang_invocation.h"
#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/frontend/hlsl_lift.h"
#include "transpiler/frontend/language_detect.h"
#include "transpiler/frontend/legacy_glsl.h"
#include "transpiler/frontend/source_limits.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <mutex>
#include <optional>

namespace stereoshift {

void ensureGlslangInitialized() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

namespace {

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
  auto [line, column] = source::lineAndColumn(input.contents, v.problemAt);
  diags.error(input.path, line, column, v.problem);
}

// What the front end decided about the input, in the result whether or not it compiles.
void recordDecisions(FrontEndResult& result, Stage stage, const LanguageDecision& decided) {
  result.info.language = decided.language;
  result.info.languageSource = decided.source;
  result.info.languageReason = decided.reason;
  result.info.stage = stage;
}

// HLSL: the entry point (-e, else as the text names it), tried on the text with its effect blocks
// blanked.
void compileHlsl(const SourceFile& input, const FrontEndOptions& options, Stage stage,
                 const LanguageDecision& decided, FrontEndResult& result, Diagnostics& diags) {
  std::set<std::string> functions = mentionedFunctions(input.contents);
  std::string entry = chooseHlslEntry(input.contents, functions, stage, options.entryPoint);
  // The text names its entry point, or the entry comes from an #include or a macro (`ENTRY(main)`),
  // which only glslang's preprocessor sees: then `main` and the stage's conventional name are tried
  // on the preprocessed shader (glslang links without an entry point, with a warning, when the name
  // is missing).
  std::vector<std::string> candidates = {entry};
  if (!functions.count(entry) && options.entryPoint.empty()) {
    candidates = {"main"};
    if (const char* conventional = conventionalHlslEntry(stage)) candidates.push_back(conventional);
  }
  auto entryMissing = [](const Diagnostics& d) {
    return std::any_of(d.all().begin(), d.all().end(), [](const Diagnostic& x) {
      return x.message.find("Entry point not found") != std::string::npos;
    });
  };
  // Effect files: glslang parses the HLSL once technique and state blocks are blanked out; the
  // idioms of decompiled shaders it refuses are lifted (hlsl_lift.h), for the analysis only.
  std::string lifted;
  std::string blanked = hlslForGlslang(input.contents, &lifted);
  Attempt a;
  bool found = false;
  for (const auto& candidate : candidates) {
    a = compileGlslangOnce(input, blanked, stage, SourceLanguage::Hlsl, Client::Vulkan, candidate, options);
    if (!entryMissing(a.diags)) {
      entry = candidate;
      found = true;
      break;
    }
  }
  if (!found) {
    diags.error(input.path, "entry point '" + entry + "' not found" +
                                (options.entryPoint.empty() ? "; name it with -e <function>" : ""));
    return;
  }
  diags.append(a.diags);
  if (!a.ok) {
    // glslang's own refusal, past the source limits and the entry-point search: for decompiled text
    // it may be glslang's gap (text_only_shift.h).
    result.glslangRejected = !a.diags.all().empty() && !entryMissing(a.diags);
    return;
  }
  result.ok = true;
  result.spirv = std::move(a.spirv);
  result.info = std::move(a.info);
  recordDecisions(result, stage, decided);
  result.info.entryPoint = entry;
  result.info.vulkan = true;
  result.info.liftedBecause = lifted;
  // Conservative: a mention in a comment only makes the injected binding skip more numbers.
  result.info.vulkanBindings = input.contents.find("vk::binding") != std::string::npos;
  result.includedFiles = std::move(a.included);
}

// GLSL: the client from the #version line. Desktop >= 400 and ES >= 310 may be Vulkan GLSL (tried
// first) or OpenGL GLSL with loose uniforms (the fallback). Older dialects are OpenGL.
void compileGlsl(const SourceFile& input, const FrontEndOptions& options, Stage stage,
                 const LanguageDecision& decided, FrontEndResult& result, Diagnostics& diags) {
  VersionLine v = findVersion(input.contents);
  if (!v.problem.empty()) {
    reportVersionProblem(input, v, diags);
    return;
  }
  std::string text = input.contents;
  // ESSL 100 and desktop 110-150 (and no #version at all): glslang makes SPIR-V only from ESSL 310 and
  // GLSL 330 on, and asked for 1xx with a SPIR-V client it fails its own built-ins and prints them to
  // stdout. Such shaders are parsed as a faithful ESSL 310 / GLSL 330 translation instead (the
  // same-language output is the original text, see glsl_splice.h), so glslang never sees 1xx here.
  LegacyDialect dialect = decideLegacyDialect(input.contents, v);
  settleVersionlessDialect(dialect, input.contents, stage);
  bool usesCompatibilityBuiltIns = false;
  bool versionPrepended = false;
  FrontEndOptions parseOptions = options;
  if (dialect.legacy && dialect.es) {
    // ESSL 100 lets a loop index pick a sampler of an array (its Appendix A's constant-index
    // expressions); ESSL 310 only with GL_EXT_gpu_shader5 (the output keeps the original text).
    parseOptions.analysisExtensions.push_back("GL_EXT_gpu_shader5");
  }
  if (dialect.legacy) {
    LegacyTranslation translated = translateLegacyGlsl(input.contents, stage, dialect, input.path);
    if (!translated.ok) {
      diags.add(translated.error);
      return;
    }
    text = std::move(translated.text);
    usesCompatibilityBuiltIns = !translated.declared.empty();
    v.version = dialect.version;
    v.es = dialect.es;
    result.dialectReason = dialect.reason;
  } else if (!dialect.versionWritten) {
    // No #version, and the text is of a version past the legacy ones (settleVersionlessDialect):
    // parsed with that version put before it (ESSL 300 as 310, as below), its lines numbered as
    // written; the output stays without one, for the loader that prepends its own.
    v.version = dialect.version;
    v.es = dialect.es;
    const int parseVersion = v.es ? std::max(v.version, 310) : v.version;
    text = "#version " + std::to_string(parseVersion) + (v.es ? " es" : "") + "\n#line 1\n" + text;
    result.dialectReason = dialect.reason;
    versionPrepended = true;
  } else if (v.es && v.version < 310) {
    // glslang 12 refuses ES < 310 for SPIR-V; parse as 310 (same line count) and emit the original.
    text.replace(v.begin, v.end - v.begin, "#version 310 es");
  }
  std::vector<Client> clients;
  bool mayBeVulkan = (!v.es && v.version >= 400) || (v.es && v.version >= 310);
  if (mayBeVulkan && options.targetEnv != TargetEnv::OpenGL45) clients.push_back(Client::Vulkan);  // --target-env opengl: GL rules only
  clients.push_back(Client::OpenGL);

  // -e NAME: the function glslang compiles as `main` (glslangValidator's --source-entrypoint).
  const std::string glslEntry = options.entryPoint.empty() ? "main" : options.entryPoint;
  std::optional<Attempt> best;
  std::optional<Attempt> vulkanButOpenGLStyle;
  for (Client client : clients) {
    Attempt a = compileGlslangOnce(input, text, stage, SourceLanguage::Glsl, client, glslEntry, parseOptions);
    if (a.ok) {
      a.info.vulkan = client == Client::Vulkan;
      // Valid as Vulkan GLSL only through the auto-mapping, with an interface written the OpenGL
      // way: OpenGL GLSL, if OpenGL rules take it (else Vulkan after all: `set`, push constants).
      if (client == Client::Vulkan && !a.openGLStyleInterface.empty() && !options.targetEnv) {
        result.dialectReason = "Vulkan GLSL only with locations and bindings made up: its " + a.openGLStyleInterface +
                               ", as OpenGL code writes it, so OpenGL GLSL";
        vulkanButOpenGLStyle = std::move(a);
        continue;
      }
      best = std::move(a);
      break;
    }
    if (!best || a.diags.errorCount() < best->diags.errorCount()) best = std::move(a);
  }
  if ((!best || !best->ok) && vulkanButOpenGLStyle) {
    best = std::move(vulkanButOpenGLStyle);
    result.dialectReason.clear();
  }
  // Refused as written: a lifted copy (glsl_lift.h) for the analysis, with OpenGL rules.
  std::string lifted;
  if (!best->ok) {
    LiftedGlsl copy = liftGlsl(text);
    if (copy.lifted) {
      Attempt a = compileGlslangOnce(input, copy.text, stage, SourceLanguage::Glsl, Client::OpenGL, glslEntry, parseOptions);
      if (a.ok) {
        a.info.vulkan = false;
        best = std::move(a);
        lifted = copy.what;
      }
    }
  }
  if (!best->ok) {
    result.glslangRejected = true;
    diags.append(best->diags);
    if (decided.source == LanguageSource::Content && v.begin == std::string::npos)
      diags.note(input.path, "parsed as GLSL (" + decided.reason + "); if this is HLSL, say so with -x hlsl");
    const auto& all = best->diags.all();
    if (options.entryPoint.empty() && std::any_of(all.begin(), all.end(), [](const Diagnostic& d) {
          return d.message.find("Missing entry point") != std::string::npos;
        }))
      diags.note(input.path, "no `main`: if another function is the entry point, name it with -e <function>");
    return;
  }
  diags.append(best->diags);  // warnings
  result.ok = true;
  result.spirv = std::move(best->spirv);
  result.info = std::move(best->info);
  recordDecisions(result, stage, decided);
  result.info.version = v.version;
  result.info.es = v.es;
  result.info.compatibilityBuiltIns = usesCompatibilityBuiltIns;
  result.info.liftedBecause = lifted;
  result.info.versionPrepended = versionPrepended;
  // An extension may give the text, at a lower version than glslang reads it at, what glslang knows
  // only at a core version (uaddCarry at 400).
  if (versionPrepended && !v.es && v.version >= 400 && enablesAnExtension(input.contents))
    result.info.spliceVersionCap = 150;
  result.info.entryPoint = "main";
  result.includedFiles = std::move(best->included);
}

}  // namespace

FrontEndResult compileToSpirv(const SourceFile& input, const FrontEndOptions& options, Diagnostics& diags,
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
  result.info.language = decided.language;
  result.info.languageSource = decided.source;
  result.info.languageReason = decided.reason;
  if (options.glslangCrashed) {
    diags.error(input.path, "glslang crashed on this input (" +
                                std::string(decided.language == SourceLanguage::Hlsl ? "HLSL" : "GLSL") +
                                " front end); it was not run again");
    result.glslangRejected = true;
    return result;
  }
  if (!options.crashedAfterFrontEnd.empty()) {
    diags.error(input.path, "stereoshift crashed on this input in " + options.crashedAfterFrontEnd +
                                "; the analysis was not run again");
    result.glslangRejected = true;
    return result;
  }
  if (decided.language == SourceLanguage::Hlsl)
    compileHlsl(input, options, *stage, decided, result, diags);
  else
    compileGlsl(input, options, *stage, decided, result, diags);
  return result;
}

}  // namespace stereoshift
