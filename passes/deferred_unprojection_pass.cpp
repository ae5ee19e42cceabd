// deferred-unprojection: not implemented yet (placeholder while the pass is written; always Unchanged).
#include "passes/pass.h"

namespace stereoshift {

namespace {

class DeferredUnprojectionPass final : public Pass {
 public:
  const char* name() const override { return "deferred-unprojection"; }
  PassResult run(PassContext&) override { return PassResult::Unchanged; }
};

}  // namespace

std::unique_ptr<Pass> createDeferredUnprojectionPass() { return std::make_unique<DeferredUnprojectionPass>(); }

}  // namespace stereoshift
