// hud-at-depth: not implemented yet (placeholder while the pass is written; always Unchanged).
#include "passes/pass.h"

namespace stereoshift {

namespace {

class HudAtDepthPass final : public Pass {
 public:
  const char* name() const override { return "hud-at-depth"; }
  PassResult run(PassContext&) override { return PassResult::Unchanged; }
};

}  // namespace

std::unique_ptr<Pass> createHudAtDepthPass() { return std::make_unique<HudAtDepthPass>(); }

}  // namespace stereoshift
