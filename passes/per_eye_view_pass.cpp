// per-eye-view: not implemented yet (placeholder while the pass is written; always Unchanged).
#include "passes/pass.h"

namespace stereoshift {

namespace {

class PerEyeViewPass final : public Pass {
 public:
  const char* name() const override { return "per-eye-view"; }
  PassResult run(PassContext&) override { return PassResult::Unchanged; }
};

}  // namespace

std::unique_ptr<Pass> createPerEyeViewPass() { return std::make_unique<PerEyeViewPass>(); }

}  // namespace stereoshift
