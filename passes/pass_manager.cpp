// See pass_manager.h. The pipeline's order and each pass's requirements live in the registry
// (pass_registry.cpp); this file only runs them and looks after the analyses in between.
#include "passes/pass_manager.h"

#include "passes/analysis/stage_interface.h"
#include "passes/ir/validate.h"
#include "passes/pass_registry.h"

namespace stereoshift {

namespace {

// With --validate-each: a pass that changed the module must not have changed what a cached analysis
// it declares preserved would say now; a wrong declaration would feed stale answers to later passes.
bool preservedAnalysesHold(PassContext& ctx, const PassInfo& info) {
  std::string stale = ctx.analyses.checkPreserved(info.preservedAnalyses);
  if (stale.empty()) return true;
  ctx.diags.error(ctx.file, std::string("internal error: pass ") + info.name + " changed the " + stale +
                                " analysis it declares preserved");
  return false;
}

}  // namespace

bool runPassPipeline(PassContext& ctx, bool* changed, std::string* passLog) {
  *changed = false;
  std::vector<const PassInfo*> passes;
  std::vector<std::string> requiredBy;
  if (ctx.options.onlyPasses.empty()) {
    for (const auto& info : passRegistry())
      if (passRunsFor(info, ctx.options)) passes.push_back(&info);
    requiredBy.resize(passes.size());
  } else {
    passes = selectPasses(ctx.options.onlyPasses, &requiredBy);
  }
  for (size_t i = 0; i < passes.size(); ++i) {
    const PassInfo& info = *passes[i];
    auto pass = info.create();
    // The cheap analyses are made before the pass; the folded copy (an optimizer run, which most
    // passes never need on most shaders) on the pass's first request.
    if (info.requiredAnalyses & kClipPositionAnalysis) ctx.analyses.clipPositions();
    int errorsBefore = ctx.diags.errorCount();
    PassResult result = pass->run(ctx);
    // An error reported from code the pass emits on the way (a helper that could not declare what
    // it needed) fails the conversion like a pass that says Failed: nothing half-made is written.
    if (result != PassResult::Failed && ctx.diags.errorCount() > errorsBefore) result = PassResult::Failed;
    ctx.record.passes.push_back({info.name, result, requiredBy[i], result == PassResult::Changed ? info.edits : kNoEdits});
    if (result == PassResult::Failed) return false;
    if (result == PassResult::Changed) {
      *changed = true;
      if (ctx.options.validateEach && !preservedAnalysesHold(ctx, info)) return false;
      ctx.analyses.invalidate(info.preservedAnalyses);
    }
    if (ctx.options.printAll && passLog)
      *passLog += "; IR after " + std::string(info.name) + " (" + toString(result) + ")\n" +
                  spirv::disassemble(ctx.module.encode());
    if (ctx.options.validateEach && result == PassResult::Changed &&
        !validateSpirv(ctx.module.encode(), ctx.source, ctx.file, std::string("after pass ") + info.name, ctx.diags,
                       ctx.frontEndSpirv))
      return false;
  }
  return true;
}

bool nextStageFactsMatter(const spirv::Module& shiftedStage, const PassOptions& options) {
  if (!options.perEyeView) return false;
  // per-eye-view looks no further than a module without a vector subtraction, unless it is told
  // the camera uniform (then it looks for that uniform's uses) or it passes a camera-like value on
  // as it is (`TangentViewPos = TBN * viewPos`: the next stage subtracts).
  return !options.cameraUniform.empty() || analysis::hasVectorSubtraction(shiftedStage) ||
         analysis::passesCameraCandidate(shiftedStage);
}

}  // namespace stereoshift
