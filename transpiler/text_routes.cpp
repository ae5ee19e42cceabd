// The routes of the driver for a stage with no SPIR-V module, as the back end's routes
// (backend/route.h) are for a stage with one: this turns D3D shader assembly into its converted
// text (the assembly route, d3dasm/asm_route.h: no front end ever reads it), and a stage glslang
// could not analyse (it refused the text, or crashed on it) into its text copied as it is, or with
// the shift spliced from the text alone (text_only_shift.h), each said in a warning and in the
// report. See stage_plan.h (writeWithoutModule).
#include "transpiler/stage_plan.h"

#include "transpiler/d3dasm/asm_route.h"
#include "transpiler/frontend/mesa_compiler.h"
#include "transpiler/source/stage_rules.h"
#include "transpiler/text_only_shift.h"

#include <algorithm>

namespace stereoshift {

namespace {
std::string demoteGlslangErrors(StagePlan& plan);

constexpr const char* kOtherUnits = "functions or a main defined in another compilation unit of its stage";

// An error glslang finds only when it links the stage: a function without its body, no entry
// point, what another unit may declare (a geometry stage's layouts in the unit with `main`).
bool isLinkError(const Diagnostic& d) {
  return d.severity == Severity::Error && (d.message.find("No function definition (body) found") != std::string::npos ||
                                           d.message.find("Missing entry point") != std::string::npos ||
                                           d.message.find("ERROR: Linking") != std::string::npos ||
                                           d.message.starts_with("Linking "));
}

// One compilation unit of a stage OpenGL links from several shader objects (the pipeline holds
// another unit of its stage), refused by glslang only at its link: its functions' bodies or its
// `main` are in another unit, which glslang, compiling one file, cannot see.
bool linkedWithOtherUnits(const StagePlan& plan, const TranspileOptions& options) {
  const auto& all = plan.diags.all();
  auto isError = [](const Diagnostic& d) { return d.severity == Severity::Error; };
  return options.stageHasOtherUnits && std::any_of(all.begin(), all.end(), isError) &&
         std::all_of(all.begin(), all.end(), [&](const Diagnostic& d) { return !isError(d) || isLinkError(d); });
}

// Whether an error of glslang's refusal is about the shader's #include files (those are the input's).
bool errorsInIncludes(const StagePlan& plan) {
  return std::any_of(plan.diags.all().begin(), plan.diags.all().end(), [&](const Diagnostic& d) {
    return d.severity == Severity::Error &&
           (d.message.find("includ") != std::string::npos || (!d.file.empty() && d.file != plan.input->path));
  });
}

// Whether glslang's refusal is of the text as one compilation unit, which a driver's compiler can
// judge alone: no link error (a function without a body, no entry point: a compiler takes what a
// link refuses) and none of the front end's own limits (kept as they are, whatever a driver takes).
bool onlyCompileErrors(const StagePlan& plan) {
  return std::none_of(plan.diags.all().begin(), plan.diags.all().end(), [](const Diagnostic& d) {
    return isLinkError(d) ||
           (d.severity == Severity::Error && d.message.find("the front end's limit") != std::string::npos);
  });
}

// What may make glslang's refusal glslang's own gap rather than the shader's error: what the text
// uses that glslang reads more narrowly than drivers (glslangGapIn), a unit of a stage linked from
// several, a crash (whatever the text), or, where glslang names none of those, a real driver's
// word: Mesa's GLSL compiler compiles the original (asked quietly: when it refuses too, glslang's
// errors are said as they are). Empty: the shader's own error.
std::string glslangsGap(StagePlan& plan, const TranspileOptions& options) {
  std::string gap = glslangGapIn(plan.input->contents);
  if (gap.empty() && linkedWithOtherUnits(plan, options)) gap = kOtherUnits;
  if (gap.empty() && options.glslangCrashed) gap = "what crashed glslang";
  if (gap.empty() && !options.crashedAfterFrontEnd.empty()) gap = "what crashed " + options.crashedAfterFrontEnd;
  if (gap.empty() && onlyCompileErrors(plan) && mesaCompilesOriginal(plan))
    gap = "what glslang refuses and Mesa's GLSL compiler compiles";
  return gap;
}

// What a stage glslang could not analyse becomes: its text as written, or its text with the shift
// spliced in by a text-only route. writeTextOutcome is the one place such a stage's record and
// output are filled.
struct TextOutcome {
  std::string output;
  bool copied = true;                             // the input as it is
  std::optional<StageRecord::TextOnly> textOnly;  // what the analysis could not do, and why
  const char* route = nullptr;                    // the text-only route that spliced it
  int spliceSites = 0;
};
bool writeTextOutcome(StagePlan& plan, Stage stage, TextOutcome outcome);
bool copiesUnshiftedStage(StagePlan& plan, const TranspileOptions& options, Stage stage, const char* route);
bool shiftHlslStageFromText(StagePlan& plan, const TranspileOptions& options, Stage stage, const char* route);
bool copyLeftToDriver(StagePlan& plan, Stage stage);
bool takeTextOnlyShift(StagePlan& plan, Stage stage, Result<TextOnlyShift> shifted, const char* route);
bool writeAssemblyStage(StagePlan& plan, const TranspileOptions& options, Stage, const char*);
// The GLSL text-only shift: only where glslang's refusal may be its own gap (the source uses what
// glslang reads more narrowly than drivers do: an #extension it enables, a line continuation, the
// compatibility profile) and no error is about the shader's #include files (those are the input's).
bool shiftGlslStageFromText(StagePlan& plan, const TranspileOptions& options, Stage stage, const char* route) {
  if (errorsInIncludes(plan) || std::any_of(plan.diags.all().begin(), plan.diags.all().end(), [](const Diagnostic& d) {
        return d.severity == Severity::Error && d.message.find("requires SPIR-V") != std::string::npos;
      }))
    return false;  // the shader's #include files, or a SPIR-V version --target-env / --target-spv gives
  // The shader's own error, said as it is.
  if (glslangsGap(plan, options).empty()) return false;
  // Never a yes to a shader the driver refuses: Mesa compiles the original, then the output.
  if (!mesaAgreesOnOriginal(plan, options, "text-only")) return false;
  StageUnits units = options.units;
  // A unit alone that declares a function it does not define calls into a unit the pipeline does
  // not hold: what that function writes is unknown, so the unit's text proves nothing 2D.
  if (!options.stageHasOtherUnits && !textDefinesEveryPrototype(plan.input->contents)) units.othersKeepUnitW = false;
  Result<TextOnlyShift> shifted = shiftFromText(*plan.input, stage, options, units);
  return takeTextOnlyShift(plan, stage, std::move(shifted), route) && checkOutputWithMesa(plan);
}

// The ways to write a stage with no SPIR-V module, as the back end's routes are for a stage with
// one: each says whether it takes the stage (cheap, without side effects), then writes it, or finds
// it cannot after all (false, with diagnostics that say why). At most one takes a stage: the
// assembly route takes assembly, and of the others (a source stage glslang could not analyse) the
// copy is for stages that get no shift, the rest for the one that does.
struct TextRoute {
  const char* name;
  // `stage` is the stage decided for a source input (Unknown for assembly: its shader model says).
  bool (*takes)(const StagePlan& plan, const TranspileOptions& options, Stage stage);
  // `route` is the route's own name, for the record and the messages.
  bool (*write)(StagePlan& plan, const TranspileOptions& options, Stage stage, const char* route);
};

// A source stage whose front end ran and which glslang refused (or crashed on): no module.
bool unanalysedSource(const StagePlan& plan) {
  return plan.kind == InputKind::Source && plan.frontEndRan && plan.front.glslangRejected && plan.stage &&
         plan.stage->stage && plan.diags.hasErrors();
}

bool shiftsFromText(const StagePlan& plan, const TranspileOptions& options, Stage stage) {
  return unanalysedSource(plan) && mayShiftFromText(stage, plan.front.info.language, options, options);
}

const TextRoute kTextRoutes[] = {
    // D3D shader assembly: shifted in its own syntax, or copied when it takes no shift.
    {"d3d-asm-splice",
     [](const StagePlan& plan, const TranspileOptions&, Stage) { return plan.kind == InputKind::D3DAssembly; },
     writeAssemblyStage},
    // A GLSL stage that takes no shift, copied as it is (copiesUnshiftedStage).
    {"unanalysed-copy",
     [](const StagePlan& plan, const TranspileOptions& options, Stage stage) {
       const bool preRaster = stage == Stage::Vertex || stage == Stage::TessEvaluation || stage == Stage::Geometry;
       const bool sameLanguage = options.target == TargetLanguage::Auto || options.target == TargetLanguage::Glsl ||
                                 options.target == TargetLanguage::Essl;
       return unanalysedSource(plan) && !(preRaster && options.shiftThisStage) && plan.front.info.language == SourceLanguage::Glsl &&
              !options.requireAnalysis && !options.forceReemit && !options.targetVersion && sameLanguage;
     },
     copiesUnshiftedStage},
    // --corrections-only: the driver shifts the position; nothing to correct without an analysis.
    {"corrections-only-copy",
     [](const StagePlan& plan, const TranspileOptions& options, Stage stage) {
       return options.correctionsOnly && shiftsFromText(plan, options, stage);
     },
     [](StagePlan& plan, const TranspileOptions&, Stage stage, const char*) { return copyLeftToDriver(plan, stage); }},
    {"hlsl-text-only",
     [](const StagePlan& plan, const TranspileOptions& options, Stage stage) {
       return !options.correctionsOnly && plan.front.info.language == SourceLanguage::Hlsl &&
              shiftsFromText(plan, options, stage);
     },
     shiftHlslStageFromText},
    {"glsl-text-only",
     [](const StagePlan& plan, const TranspileOptions& options, Stage stage) {
       return !options.correctionsOnly && plan.front.info.language == SourceLanguage::Glsl &&
              shiftsFromText(plan, options, stage);
     },
     shiftGlslStageFromText},
};

}  // namespace

bool writeWithoutModule(StagePlan& plan, const TranspileOptions& options) {
  const Stage stage = plan.stage && plan.stage->stage ? *plan.stage->stage : Stage::Unknown;
  for (const TextRoute& route : kTextRoutes)
    if (route.takes(plan, options, stage)) return route.write(plan, options, stage, route.name);
  return false;
}

namespace {

// A GLSL stage that takes no shift (fragment, tessellation control, compute, or a pre-rasterization
// stage before the one a pipeline shifts) which glslang refuses for what it reads more narrowly than
// drivers (an #extension, a line continuation, the compatibility profile) or crashes on: the output
// would be its input unless a per-eye fix applied, so it is copied unchanged with a warning that no
// fix was looked for, and the rest of the pipeline converts. Not with --require-analysis, another
// output language or version, or errors in its #include files (those are the input's).
bool copiesUnshiftedStage(StagePlan& plan, const TranspileOptions& options, Stage stage, const char* route) {
  if (errorsInIncludes(plan)) return false;
  const std::string gap = glslangsGap(plan, options);
  if (gap.empty()) return false;
  if (!mesaAgreesOnOriginal(plan, options, route)) return false;
  const std::string file = plan.input->path;
  const std::string reason = demoteGlslangErrors(plan);
  plan.diags.warning(file, "glslang cannot analyse this " + std::string(stageName(stage)) + " stage (its text has " +
                               gap + "); it takes no shift, so it is copied unchanged, without the per-eye fixes an "
                               "analysis might find; --require-analysis makes this an error");
  TextOutcome copy{plan.input->contents};
  copy.textOnly = StageRecord::TextOnly{reason, {"per-eye view vectors", "deferred unprojection"}, {}, true};
  return writeTextOutcome(plan, stage, std::move(copy));
}

bool shiftHlslStageFromText(StagePlan& plan, const TranspileOptions& options, Stage stage, const char* route) {
  // Decompiled text only: the D3D compiler accepted what it was decompiled from, so glslang's
  // refusal (or crash) is glslang's; hand-written HLSL glslang refuses keeps its errors.
  if (!isDecompiledHlsl(*plan.input)) return false;
  for (const auto& d : plan.diags.all())
    if (d.severity == Severity::Error && !d.file.empty() && d.file != plan.input->path) return false;  // an #include's
  // Never past an error of the text's own: the D3D compiler did not compile that.
  if (auto own = ownTextError(*plan.input)) {
    plan.diags.add(*own);
    std::string note = "the decompiled text is broken itself, so no D3D compiler made it: the text-only shift is not "
                       "taken";
    if (stageOfDecompiledDump(plan.input->path))
      note += "; 3Dmigoto's assembly dump of the same shader (" +
              plan.input->path.substr(0, plan.input->path.size() - std::string("_replace.txt").size()) +
              ".txt, export_shaders with asm) goes through the assembly route without a decompiler";
    plan.diags.note(plan.input->path, note);
    return false;
  }
  return takeTextOnlyShift(plan, stage, shiftHlslFromText(*plan.input, stage, options), route);
}

// glslang's errors said as warnings: they say what it could not analyse, and the shader goes to its
// driver as written. Returns the first of them.
std::string demoteGlslangErrors(StagePlan& plan) {
  Diagnostics kept;
  std::string first;
  for (Diagnostic d : plan.diags.all()) {
    if (d.severity == Severity::Error) {
      if (first.empty()) first = d.format();
      d.severity = Severity::Warning;
    }
    kept.add(std::move(d));
  }
  plan.diags = std::move(kept);
  return first;
}

// --corrections-only, a pre-rasterization stage glslang cannot analyse: the driver shifts its
// position, and no correction can be found without an analysis: the input as it is, said so.
bool copyLeftToDriver(StagePlan& plan, Stage stage) {
  const std::string& file = plan.input->path;
  demoteGlslangErrors(plan);
  plan.diags.warning(file, "glslang cannot analyse this shader; with --corrections-only its position is left to the driver "
                     "and no correction is looked for: copied unchanged");
  return writeTextOutcome(plan, stage, TextOutcome{plan.input->contents});
}

bool takeTextOnlyShift(StagePlan& plan, Stage stage, Result<TextOnlyShift> shifted, const char* route) {
  const std::string& file = plan.input->path;
  if (!shifted) {
    plan.diags.note(file, "no shift from the text alone either: " + shifted.error().message);
    return false;
  }
  std::string reason = demoteGlslangErrors(plan);
  if (shifted->copiedAs) {
    const Classification as = *shifted->copiedAs;
    const std::string why = as == Classification::ConstantW1
                                ? "its text writes gl_Position with the literal w = 1 only (a 2D stage, which the "
                                  "runtime cutoff would keep mono in both eyes)"
                            : as == Classification::NoVertexEmitted
                                ? "no unit of this geometry stage emits a vertex (EmitVertex, EmitStreamVertex): it "
                                  "rasterizes nothing"
                                : "no unit of this stage names gl_Position: it writes no clip position";
    plan.diags.warning(file, "glslang cannot analyse this shader; " + why +
                                 ", so it is copied unchanged; --require-analysis makes this an error");
    plan.record.classification = *shifted->copiedAs;
    TextOutcome copy{std::move(shifted->output)};
    copy.textOnly = StageRecord::TextOnly{reason, {"per-eye view vectors", "deferred unprojection"}, {}, true};
    return writeTextOutcome(plan, stage, std::move(copy));
  }
  std::string notDone;
  for (const auto& what : shifted->notDone) notDone += (notDone.empty() ? "" : ", ") + what;
  plan.diags.warning(file, "glslang cannot analyse this shader: the clip-space shift was spliced from the text alone (not "
                           "done: " + notDone + "); --require-analysis makes this an error");
  TextOutcome spliced{std::move(shifted->output), false};
  spliced.textOnly = StageRecord::TextOnly{reason, shifted->notDone, shifted->eyeParams};
  spliced.route = route;
  spliced.spliceSites = shifted->sites;
  return writeTextOutcome(plan, stage, std::move(spliced));
}

// The assembly route (d3dasm/asm_route.h) writing into the plan: its record, its warnings and text,
// or its error.
bool writeAssemblyStage(StagePlan& plan, const TranspileOptions& options, Stage, const char*) {
  Result<ConvertedAssembly> converted = convertAssembly(*plan.input, options, plan.record, plan.diags);
  if (!converted) {
    plan.diags.add(located(converted.error(), plan.input->path));
    return false;
  }
  plan.record.totalMs = msSince(plan.started);
  plan.output = std::move(converted->text);
  plan.copied = converted->copied;
  plan.changed = !converted->copied;
  return true;
}

bool writeTextOutcome(StagePlan& plan, Stage stage, TextOutcome outcome) {
  StageRecord& record = plan.record;
  record.stage = stage;
  record.stageReason = plan.stage->reason;
  if (outcome.textOnly) record.textOnly = std::move(*outcome.textOnly);
  if (outcome.route) {
    record.emit.route = outcome.route;
    record.emit.spliceSites = outcome.spliceSites;
  }
  record.output = outcome.copied ? StageRecord::Output::Copied : StageRecord::Output::Emitted;
  record.totalMs = msSince(plan.started);
  plan.output = std::move(outcome.output);
  plan.copied = outcome.copied;
  plan.changed = !outcome.copied;
  return true;
}

}  // namespace

}  // namespace stereoshift
