// The pass manager: runs the registered passes (pass_registry.h) in pipeline order on one shader,
// keeps the context's analyses valid between them, and answers the one pipeline-wide question a
// stage's passes ask of another stage (the next stage's facts).
#pragma once

#include "passes/next_stage_facts.h"
#include "passes/pass.h"

#include <string>

namespace stereoshift {

// Runs the passes on ctx.module: all of them, or with --pass (options.onlyPasses) the named ones
// and the passes they require, which the report marks `"required_by": NAME`. After a pass that
// changed the module, the analyses it does not preserve are dropped (with --validate-each the ones
// it claims to preserve are checked against a fresh computation first). Returns false when a pass
// failed (diagnostics say why). `changed` reports whether any pass changed the module.
bool runPassPipeline(PassContext& ctx, bool* changed, std::string* passLog);

// ---- the next-stage facts of a pipeline (for per-eye-view in the last pre-rasterization stage) ----

// Whether the facts can matter to `shiftedStage` at all: cheap, so that the consuming stage's
// folded copy (an optimizer run) is made only when per-eye-view would look at them.
bool nextStageFactsMatter(const spirv::Module& shiftedStage, const TranspileOptions& options);
// The facts of the consuming (fragment) stage whose context this is; its folded copy stays cached in
// `consumer` for that stage's own passes. Changes nothing.
NextStageFacts analyseNextStage(PassContext& consumer);
// The facts carried back through a stage between (geometry, tessellation) whose own consumer is
// `middle.nextStage`: what the stage before must know about the outputs it writes to `middle`.
NextStageFacts carryNextStageFacts(PassContext& middle);

}  // namespace stereoshift
