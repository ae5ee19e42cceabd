// The driver: one stage is a straight line through its plan (stage_plan.h): read, parse, choose its
// options, run the passes, emit through the first back-end route that takes it, render the report.
// A pipeline plans every stage first (the stage each input is, its front end, the binding the eye
// parameters may take, how the next stage uses each stage's outputs), then converts each.
#include "transpiler/stereoshift.h"

#include "passes/pass_manager.h"
#include "transpiler/d3dasm/asm_route.h"
#include "transpiler/d3dasm/asm_text.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"
#include "transpiler/stage_plan.h"
#include "transpiler/text_only_shift.h"

#include <algorithm>

namespace stereoshift {

const char* version() { return STEREOSHIFT_VERSION; }

std::string defaultOutputExtension(const SourceFile& input, const TranspileOptions& options) {
  switch (options.target) {
    case TargetLanguage::Spirv: return ".spv";
    case TargetLanguage::SpirvAsm: return ".spvasm";
    case TargetLanguage::Msl: return ".metal";
    case TargetLanguage::Hlsl: return ".hlsl";
    default: break;
  }
  auto dot = input.path.find_last_of('.');
  return dot == std::string::npos ? std::string() : input.path.substr(dot);
}

namespace {

// Steps 1 to 5 of stage_plan.h on `plan`, then the result and its report. A stage with no SPIR-V
// module (assembly, or a source glslang could not parse) takes a route for such stages instead.
TranspileResult convertStage(StagePlan& plan, const TranspileOptions& options) {
  plan.started = std::chrono::steady_clock::now();
  bool ok = plan.kind == InputKind::Source && readStage(plan, options) && parseStage(plan, options);
  bool fromText = !ok && writeWithoutModule(plan, options);
  if (ok) {
    chooseStageOptions(plan, options);
    ok = runStagePasses(plan) && emitStage(plan) && checkOutputWithMesa(plan);
  }
  TranspileResult result;
  ok = ok || fromText;
  result.ok = ok;
  result.changed = fromText || (plan.record.classification && plan.changed);
  result.copiedThrough = ok && plan.copied;
  if (ok) {
    result.output = std::move(plan.output);
    result.binaryOutput = plan.binaryOutput;
  }
  result.diagnostics = std::move(plan.diags);
  result.includedFiles = plan.includedFiles;
  result.passLog = std::move(plan.passLog);
  result.originalSpirv = plan.words;
  result.source = plan.info;
  result.report = renderStageReport(plan.record);
  // The errors and warnings as they were printed, for a tool that reads the report alone.
  for (const Diagnostic& d : result.diagnostics.all())
    if (d.severity == Severity::Error || d.severity == Severity::Warning)
      result.report[d.severity == Severity::Error ? "errors" : "warnings"].push_back(d.format());
  result.record = std::move(plan.record);
  return result;
}

// Whether a GLSL text defines `void main(`: a code token `main` after `void`, before `(`.
bool definesMain(const SourceFile& input) {
  source::LexedText lexed(input.contents);
  size_t previous = lexed.size();
  for (size_t k = 0; k < lexed.size(); ++k) {
    if (!lexed[k].isCode()) continue;
    if (lexed.isIdentifier(k) && lexed.text(k) == "main" && previous < lexed.size() && lexed.text(previous) == "void" &&
        lexed.isPunct(lexed.nextNonComment(k), '('))
      return true;
    previous = k;
  }
  return false;
}

// Of several compilation units of the stage that gets the shift, which takes it: the one that
// defines `main` (its wrapper shifts what the others write), or, in a geometry stage, the one that
// emits the vertices (the shift goes before each emit, wherever `main` is).
int shiftPreference(std::optional<Stage> stage, const SourceFile& input) {
  if (stage == Stage::Geometry && textCallsEmit(input.contents)) return 2;  // where its vertices are emitted
  return definesMain(input) ? 1 : 0;
}

// What the other compilation units of stage plan `i` (those `isOther` names) say by their text
// (transpile_options.h, StageUnits); read only for a stage linked from several units.
template <typename IsOther>
StageUnits stageUnits(const std::vector<std::unique_ptr<StagePlan>>& plans, size_t i, IsOther isOther) {
  StageUnits units;
  const StagePlan& self = *plans[i];
  std::vector<const SourceFile*> others;
  for (const auto& other : plans)
    if (isOther(other)) others.push_back(other->input);
  // One unit alone: what another might hold is unknown (a function without its body may emit).
  if (others.empty()) return units;
  const bool geometry = self.stage && self.stage->stage == Stage::Geometry;
  auto all = [&](auto test) {
    return std::all_of(others.begin(), others.end(), [&](const SourceFile* f) { return f && test(f->contents); });
  };
  auto any = [&](auto test) {
    return std::any_of(others.begin(), others.end(), [&](const SourceFile* f) { return f && test(f->contents); });
  };
  units.otherWritesPosition = any(textWritesPosition);
  units.othersKeepUnitW = all(textKeepsUnitW);
  if (geometry) units.stageEmits = textCallsEmit(self.input->contents) || any(textCallsEmit);
  units.noUnitNamesPosition = all([](const std::string& t) { return !textNamesPosition(t); }) &&
                              !textNamesPosition(self.input->contents);
  return units;
}

// A pipeline has one shader per stage; OpenGL may link one stage from several compilation units,
// of which one defines `main`. Two GLSL units of one stage that each define `main` are two shaders
// (`--pipeline a.vert,b.vert`): the second would be left mono without a word. Refused: every stage
// fails, the error on the second unit.
std::optional<std::vector<TranspileResult>> twoShadersOfOneStage(const std::vector<SourceFile>& stages,
                                                                 const std::vector<std::unique_ptr<StagePlan>>& plans) {
  for (size_t j = 0; j < plans.size(); ++j)
    for (size_t i = 0; i < j; ++i) {
      const StagePlan& a = *plans[i];
      const StagePlan& b = *plans[j];
      bool glsl = a.kind == InputKind::Source && b.kind == InputKind::Source && a.info.language == SourceLanguage::Glsl &&
                  b.info.language == SourceLanguage::Glsl;
      if (!glsl || !a.stage || !b.stage || !a.stage->stage || a.stage->stage != b.stage->stage ||
          !definesMain(stages[i]) || !definesMain(stages[j]))
        continue;
      std::vector<TranspileResult> results(stages.size());
      results[j].diagnostics.error(stages[j].path, std::string("--pipeline: ") + stages[i].path + " and " +
                                                       stages[j].path + " are both -S " + stageName(*a.stage->stage) +
                                                       " shaders with their own main; a pipeline has one shader per "
                                                       "stage (linked from several units, only one defines main): "
                                                       "convert them in pipelines of their own");
      return results;
    }
  return std::nullopt;
}

// Pipeline order of the stages that come before rasterization; 0 for the others (tessellation
// control, fragment, compute, task: never shifted).
int shiftRank(std::optional<Stage> stage) {
  if (!stage) return 0;
  switch (*stage) {
    case Stage::Vertex: return 1;
    case Stage::TessEvaluation: return 2;
    case Stage::Geometry: return 3;
    case Stage::Mesh: return 4;
    default: return 0;
  }
}

// The order a view vector is handed on in: vertex, tessellation control, evaluation, geometry.
int flowOrder(std::optional<Stage> stage) {
  if (!stage) return -1;
  switch (*stage) {
    case Stage::Vertex: return 0;
    case Stage::TessControl: return 1;
    case Stage::TessEvaluation: return 2;
    case Stage::Geometry: return 3;
    default: return -1;
  }
}

using Plans = std::vector<std::unique_ptr<StagePlan>>;

// The injected block must not take a binding another stage of the pipeline uses.
TranspileOptions pipelineBinding(const Plans& plans, const TranspileOptions& options) {
  TranspileOptions chosen = options;
  if (plans.size() < 2 || options.eye.binding || options.eye.hlslRegister) return chosen;
  std::optional<uint32_t> highest;
  bool hlsl = false;
  for (const auto& plan : plans) {
    if (!plan->analyses) continue;
    hlsl |= plan->front.info.language == SourceLanguage::Hlsl;
    auto stageHighest = highestBinding(*plan->module, options.eye.descriptorSet.value_or(0), perClassRegisters(plan->front.info));
    if (stageHighest) highest = std::max(highest.value_or(0), *stageHighest);
  }
  if (highest) {
    if (hlsl) chosen.eye.hlslRegister = *highest + 1;
    else chosen.eye.binding = *highest + 1;
  }
  return chosen;
}

// How the fragment stage uses its inputs (for per-eye-view), handed to the last pre-rasterization
// stage and carried back through the stages between (a geometry stage passing TangentViewPos on).
void handOnNextStageFacts(Plans& plans, const TranspileOptions& options, int last) {
  if (!options.perEyeView || last < 0) return;  // no stage to hand them to
  // per-eye-view in a pre-rasterization stage looks no further when that stage has no vector
  // subtraction: then the fragment stage's folded copy (an optimizer run, most of a typical
  // fragment shader's cost) is not worth making.
  bool matter = false;
  for (const auto& plan : plans) {
    if (plan->stage->stage == Stage::Fragment || plan->stage->stage == Stage::Compute) continue;
    matter |= !plan->analyses || nextStageFactsMatter(*plan->module, options);
  }
  if (!matter) return;
  auto fragment = std::find_if(plans.begin(), plans.end(), [](const auto& p) { return p->stage->stage == Stage::Fragment; });
  if (fragment == plans.end() || !(*fragment)->analyses) return;  // reported when the stage converts
  plans[static_cast<size_t>(last)]->nextStage = (*fragment)->analyses->stageInputUses();
  for (size_t after = static_cast<size_t>(last);;) {
    std::optional<size_t> before;
    for (size_t i = 0; i < plans.size(); ++i) {
      int order = flowOrder(plans[i]->stage->stage);
      if (order >= 0 && order < flowOrder(plans[after]->stage->stage) &&
          (!before || order > flowOrder(plans[*before]->stage->stage)))
        before = i;
    }
    if (!before || !plans[after]->analyses) break;
    plans[*before]->nextStage = plans[after]->analyses->stageInputUses(&*plans[after]->nextStage);
    after = *before;
  }
}

// A 3Dmigoto dump (named `<hash>-<stage>[_replace].txt`, or with 3Dmigoto's header or declarations)
// takes its eye parameters where 3Dmigoto puts them, its StereoParams texture (t125), unless the
// options say where (--eye-source, single-pass stereo) or ask for what only other eye parameters
// can be (another output language, a re-emit): a dump converted without --eye-source 3dmigoto would
// otherwise get a cbuffer 3Dmigoto never fills, a shader that stays mono in the game. D3D assembly
// reads the texture always (d3dasm/asm_route.h): `input` is a source input, never assembly.
bool takes3DMigotoEyeParamsByDefault(const SourceFile& input, const TranspileOptions& options) {
  return !options.eyeFrom3DMigoto && options.eye.source == EyeSource::Auto &&
         options.eye.select == EyeSelect::Parameter && !options.forceReemit &&
         (options.target == TargetLanguage::Auto || options.target == TargetLanguage::Hlsl) &&
         (isDecompiledHlsl(input) || stageOf3DMigotoDump(input.path));
}

// Says so on a stage converted with the default: a note and the report.
void note3DMigotoDefault(const SourceFile& input, TranspileResult& result) {
  result.diagnostics.note(input.path,
                          "a 3Dmigoto dump: its eye parameters are read from 3Dmigoto's StereoParams texture (t125), "
                          "where 3Dmigoto puts them (--eye-source uniform-block or another puts them elsewhere)");
  result.report["eye_params_default"] = "3Dmigoto dump: its StereoParams texture (t125)";
}

}  // namespace

InputKind decideInputKind(const SourceFile& input) {
  // By content: its first line that is not a comment is a shader-model line (vs_5_0, ...).
  return d3dasm::isD3DAssembly(input.contents) ? InputKind::D3DAssembly : InputKind::Source;
}

TranspileResult transpile(const SourceFile& input, const TranspileOptions& options) {
  StagePlan plan;
  plan.input = &input;
  plan.kind = decideInputKind(input);
  if (plan.kind != InputKind::Source || !takes3DMigotoEyeParamsByDefault(input, options))
    return convertStage(plan, options);
  TranspileOptions dump = options;
  readEyeParamsFrom3DMigoto(dump);
  TranspileResult result = convertStage(plan, dump);
  note3DMigotoDefault(input, result);
  return result;
}

std::vector<TranspileResult> transpilePipeline(const std::vector<SourceFile>& stages, const TranspileOptions& options) {
  std::vector<InputKind> kinds;
  for (const auto& stage : stages) kinds.push_back(decideInputKind(stage));
  // A pipeline of 3Dmigoto dumps (assembly or decompiled) takes 3Dmigoto's eye parameters by default.
  bool dumps = false, others = false;
  for (size_t i = 0; i < stages.size(); ++i)
    if (kinds[i] == InputKind::Source) (takes3DMigotoEyeParamsByDefault(stages[i], options) ? dumps : others) = true;
  const bool dumpDefault = dumps && !others;
  TranspileOptions pipelineOptions = options;
  if (dumpDefault) readEyeParamsFrom3DMigoto(pipelineOptions);
  // Every stage decided once; each source stage through the front end once, its module parsed for
  // the questions below; the conversion of each stage reuses all of it.
  Plans plans;
  int last = -1, lastRank = 0;  // the last pre-rasterization stage gets the shift
  for (size_t i = 0; i < stages.size(); ++i) {
    auto plan = std::make_unique<StagePlan>();
    plan->input = &stages[i];
    plan->kind = kinds[i];
    const bool assembly = kinds[i] == InputKind::D3DAssembly;
    if (assembly) {
      // No front end (the assembly route reads it); its stage is its shader model's.
      plan->stage.emplace();
      plan->stage->stage = assemblyStage(stages[i]);
    } else {
      plan->stage = decideInputStage(stages[i], pipelineOptions);
    }
    // Of several compilation units of the last stage (OpenGL links a stage from several shader
    // objects), the one shiftPreference says takes the shift.
    if (int rank = shiftRank(plan->stage->stage);
        rank > lastRank || (rank > 0 && rank == lastRank && shiftPreference(plan->stage->stage, stages[i]) >
                                                                shiftPreference(plans[last]->stage->stage, stages[last]))) {
      last = static_cast<int>(i);
      lastRank = rank;
    }
    if (!assembly && goesThroughFrontEnd(stages[i])) {
      runFrontEnd(*plan, pipelineOptions);
      parseEarly(*plan, pipelineOptions);
    }
    plans.push_back(std::move(plan));
  }
  if (auto refused = twoShadersOfOneStage(stages, plans)) return std::move(*refused);
  pipelineOptions = pipelineBinding(plans, pipelineOptions);
  handOnNextStageFacts(plans, pipelineOptions, last);
  std::vector<TranspileResult> results;
  for (size_t i = 0; i < plans.size(); ++i) {
    TranspileOptions stageOptions = pipelineOptions;
    stageOptions.shiftThisStage = static_cast<int>(i) == last;
    auto otherUnit = [&](const auto& other) {
      return other != plans[i] && other->stage && plans[i]->stage && other->stage->stage &&
             other->stage->stage == plans[i]->stage->stage;
    };
    stageOptions.stageHasOtherUnits = std::any_of(plans.begin(), plans.end(), otherUnit);
    stageOptions.units = stageUnits(plans, i, otherUnit);
    results.push_back(convertStage(*plans[i], stageOptions));
    if (dumpDefault && kinds[i] == InputKind::Source) note3DMigotoDefault(stages[i], results.back());
  }
  return results;
}

}  // namespace stereoshift
