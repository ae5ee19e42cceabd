// The driver's plan of one stage: everything decided about it once, in the order the driver decides
// it (stage_plan.cpp has one function per step):
//   1. read      the input's kind (SPIR-V, source), the stage and why (decided once, also for a
//                pipeline's ordering), the front end's result (language, dialect, SPIR-V, includes)
//   2. parse     the module in the IR and its analysis manager
//   3. options   the options this stage converts with: the pipeline's binding, whether it is the
//                shifted stage, a version a single-pass mode raises the output to, the eye source a
//                route needs
//   4. passes    the pass pipeline on the module (its run record in the context)
//   5. emit      the first back-end route that accepts the stage writes it, and the driver
//                re-compiles what it wrote (backend/route.h)
// An HLSL file with several vertex entry points is expanded before the passes into one plan per
// entry point (`otherEntries`); their passes run when the splice route needs them.
#pragma once

#include "passes/analysis_manager.h"
#include "core/diagnostics.h"
#include "passes/ir/module.h"
#include "passes/pass.h"
#include "transpiler/backend/route.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/mesa_compiler.h"
#include "transpiler/report.h"
#include "transpiler/stereoshift.h"
#include "transpiler/transpile_options.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

struct StagePlan {
  const SourceFile* input = nullptr;
  TranspileOptions options;          // as this stage converts
  Diagnostics diags;
  StageRecord record;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

  // 1. read
  InputKind kind = InputKind::Source;  // decided once, before the plan (decideInputKind)
  bool spirvInput = false;
  std::optional<StageDecision> stage;  // source inputs: decided once
  bool frontEndRan = false;
  FrontEndResult front;
  double frontEndMs = 0;               // a pipeline runs every front end first
  SourceInfo info;
  std::vector<uint32_t> words;         // the input as the front end made it, before any pass
  std::vector<std::string> includedFiles;
  // Mesa's word on the input's text where glslang refused it, asked once (stage_plan.cpp).
  std::optional<MesaVerdict> originalMesaVerdict;
  // 2. parse
  std::optional<spirv::Module> module;
  std::unique_ptr<AnalysisManager> analyses;
  // 3. options
  std::optional<NextStageFacts> nextStage;  // how the next stage uses this stage's outputs
  // 4. passes
  std::unique_ptr<PassContext> context;
  bool changed = false;
  std::string passLog;
  // The other entry points of an HLSL file (see the file comment), and their plans.
  std::vector<OtherEntryPoint> otherEntries;
  std::vector<std::unique_ptr<StagePlan>> entryPlans;
  // 5. emit
  std::string output;
  bool binaryOutput = false;
  bool copied = false;
};

// Whether an input is SPIR-V (its magic number, or a .spv name), and whether it goes through the front end.
bool isSpirvInput(const SourceFile& input);
// After step 5, for a GLSL stage whose original only Mesa vouched for (the lifted copy's splice):
// the output must compile in Mesa too (frontend/mesa_compiler.h); false, with the error, when not.
bool checkOutputWithMesa(StagePlan& plan);
// Whether Mesa's GLSL compiler compiles the original text of a GLSL stage glslang refused, asked
// quietly: the stage's diagnostics are left as they are whatever the answer (no verdict: false).
bool mesaCompilesOriginal(StagePlan& plan);
// Mesa's word on the original text of a GLSL stage that `route` would take where glslang did not
// say yes as written: true when the route may go on (see stage_plan.cpp).
bool mesaAgreesOnOriginal(StagePlan& plan, const TranspileOptions& options, const char* route);
bool goesThroughFrontEnd(const SourceFile& input);
// The front end, run ahead of the other steps (a pipeline parses every stage first); `parseEarly`
// then parses its module for the questions a pipeline asks across stages (false when it cannot:
// the stage's own conversion reports why).
void runFrontEnd(StagePlan& plan, const TranspileOptions& options);
bool parseEarly(StagePlan& plan, const TranspileOptions& options);
// Steps 1 and 2: false (the reason in plan.diags) when the stage cannot be converted.
bool readStage(StagePlan& plan, const TranspileOptions& options);
bool parseStage(StagePlan& plan, const TranspileOptions& options);
// The routes for a stage with no SPIR-V module (text_routes.cpp), as the back end's routes are for
// one with a module: D3D shader assembly (its own reader and printer, no front end), and a GLSL or
// HLSL stage steps 1 and 2 could not parse, which the text-only shift (text_only_shift.h) writes
// instead, or copies, the front end's errors becoming warnings, when the options allow it and the
// text is enough. False (plan.diags says why, a source stage's errors kept) when none writes it.
bool writeWithoutModule(StagePlan& plan, const TranspileOptions& options);
// Step 1 for the stages of a pipeline, before anything else: the stage each input is, decided once.
StageDecision decideInputStage(const SourceFile& input, const TranspileOptions& options);
// Step 3: the options the plan converts with, from those given.
void chooseStageOptions(StagePlan& plan, const TranspileOptions& options);
// Step 4.
bool runStagePasses(StagePlan& plan);
// Step 5.
bool emitStage(StagePlan& plan);

double msSince(std::chrono::steady_clock::time_point start);

}  // namespace stereoshift
