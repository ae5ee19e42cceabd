// The pass manager: runs the registered passes (pass_registry.h) in pipeline order on one shader,
// records each one's status in the context's run record, and keeps the context's analyses valid
// between them (dropping what a pass that changed the module does not preserve).
#pragma once

#include "passes/pass.h"

#include <string>

namespace stereoshift {

// Runs the passes on ctx.module: all of them, or with --pass (options.onlyPasses) the named ones
// and the passes they require, recorded with the named pass that required them. After a pass that
// changed the module, the analyses it does not preserve are dropped (with --validate-each the ones
// it claims to preserve are checked against the module first). Returns false when a pass failed
// (diagnostics say why). `changed` reports whether any pass changed the module; `passLog` receives
// the --print-all dumps.
bool runPassPipeline(PassContext& ctx, bool* changed, std::string* passLog);

// Whether the next stage's facts can matter to `shiftedStage` at all: cheap, so that the consuming
// stage's folded copy (an optimizer run) is made only when per-eye-view would look at them.
bool nextStageFactsMatter(const spirv::Module& shiftedStage, const PassOptions& options);

}  // namespace stereoshift
