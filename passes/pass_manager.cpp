#include "passes/pass_manager.h"
#include "passes/ir/validate.h"

#include <algorithm>

namespace stereoshift {

namespace {

struct PipelineEntry {
  std::unique_ptr<Pass> (*create)();
};

// The order matters:
//  1. clip-position-detection is analysis only: it classifies the shader; the geometry passes
//     below do nothing unless it found a perspective last stage.
//  2. hud-at-depth (opt-in) turns a proven-2D position into one at an eye depth, which then needs
//     the shift like any perspective position: it must come before eye-params, halo and the shift.
//  3. eye-params declares eyeSign / separation / convergence; the shift and halo code load them.
//  4. halo runs before the shift, while the only loads of the position are the application's own,
//     so it sees exactly the values the application derived its outputs from.
//  5. stereo-shift guards and shifts the final position at every return / emit.
//  6. per-eye-view and deferred-unprojection fix pixel maths that sees the mono eye; they are
//     independent of the shift (they also run on fragment shaders, which get no shift) and declare
//     the eye parameters they need themselves.
const PipelineEntry kPipeline[] = {
    {createClipPositionDetectionPass},
    {createHudAtDepthPass},
    {createEyeParamsPass},
    {createHaloPass},
    {createStereoShiftPass},
    {createPerEyeViewPass},
    {createDeferredUnprojectionPass},
};

}  // namespace

bool runPassPipeline(PassContext& ctx, bool* changed, std::string* passLog) {
  *changed = false;
  for (const auto& entry : kPipeline) {
    auto pass = entry.create();
    const auto& only = ctx.options.onlyPasses;
    if (!only.empty() && std::find(only.begin(), only.end(), pass->name()) == only.end()) continue;
    PassResult result = pass->run(ctx);
    ctx.report["passes"][pass->name()]["result"] = toString(result);
    if (result == PassResult::Failed) return false;
    if (result == PassResult::Changed) *changed = true;
    if (ctx.options.printAll && passLog)
      *passLog += "; IR after " + std::string(pass->name()) + " (" + toString(result) + ")\n" +
                  spirv::disassemble(ctx.module.encode());
    if (ctx.options.validateEach && result == PassResult::Changed &&
        !validateSpirv(ctx.module.encode(), ctx.source, ctx.file, std::string("after pass ") + pass->name(),
                       ctx.diags))
      return false;
  }
  return true;
}

}  // namespace stereoshift
