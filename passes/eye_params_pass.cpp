// eye-params: turns a shader that needs the shift into one that declares the eye parameters
// eyeSign, separation and convergence (as --eye-source says: a uniform block / cbuffer, push-constant
// members, loose OpenGL uniforms or specialization constants; eye_param_emitter.h does the work,
// and passes that need more parameters ask it themselves). Names that clash with the
// application's own are renamed (and recorded), never aliased.
#include "passes/eye_param_emitter.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"

namespace stereoshift {

namespace {

class EyeParamsPass final : public Pass {
 public:
  const char* name() const override { return "eye-params"; }

  // Declares eyeSign, separation and convergence in a shader that gets the shift; passes that need
  // more (or that fix a shader that gets no shift) call ensureEyeParams() themselves.
  PassResult run(PassContext& ctx) override {
    if (!ctx.shiftPosition || ctx.eyeDeclared) return PassResult::Unchanged;
    return ensureEyeParams(ctx, kConvergence + 1) ? PassResult::Changed : PassResult::Failed;
  }
};

}  // namespace

std::unique_ptr<Pass> createEyeParamsPass() { return std::make_unique<EyeParamsPass>(); }

// Adds a declaration only: no output, no pointer to the position, no application value changes
// (but new globals: the value-flow and value-number indexes point into what moved).
PassInfo eyeParamsPassInfo() {
  return {"eye-params", createEyeParamsPass,
          "declares eyeSign, separation and convergence in a shader that gets the shift",
          "always (--eye-source chooses how)",
          "the shift and halo code load the parameters it declares",
          {"clip-position-detection"}, kNoAnalyses, kKeptByDeclarations, editSet(EditKind::EyeParameters)};
}

}  // namespace stereoshift
