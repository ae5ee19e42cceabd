// The front end (see front_end.h): this turns a shader file into SPIR-V. It decides the stage and
// the language, refuses text past the source limits, then hands the text to the dialect of its
// language (dialect.h: HLSL with its entry point, GLSL by its #version). glslang itself is run by
// glslang_invocation.cpp, #include resolved by include_resolver.cpp; recompile.cpp checks output.
#include "transpiler/frontend/front_end.h"

#include "transpiler/frontend/dialect.h"
#include "transpiler/frontend/glslang_invocation.h"
#include "transpiler/frontend/language_detect.h"
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
  dialectOf(decided.language).compile(input, options, *stage, decided, result, diags);
  return result;
}

}  // namespace stereoshift
