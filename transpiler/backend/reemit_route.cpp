// See reemit_route.h. The module is copied and stripped of the qualifiers glslang had to
// auto-assign (emit_prep.h) before SPIRV-Cross sees it; every GLSL / ESSL / HLSL text it writes is
// compiled again before it is written (not only under --verify): a target that cannot express the
// shader (a Vulkan construct at an OpenGL version, a built-in a dialect lacks) is refused with
// glslang's reason instead of becoming a file that does not compile. MSL has no compiler here.
#include "transpiler/backend/reemit_route.h"

#include "transpiler/backend/back_end.h"
#include "transpiler/backend/emit_prep.h"
#include "passes/eye_select.h"  // glslOutputVersion

namespace stereoshift {

namespace {

const char* targetWord(TargetLanguage t) {
  switch (t) {
    case TargetLanguage::Glsl: return "glsl";
    case TargetLanguage::Essl: return "essl";
    case TargetLanguage::Hlsl: return "hlsl";
    case TargetLanguage::Msl: return "msl";
    default: return "?";
  }
}

class ReemitRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "spirv-cross"; }
  RouteDecision accepts(const EmitRequest&) const override { return RouteDecision::accept(); }

  EmitResult emit(const EmitRequest& r, EmitFacts&, Diagnostics& diags) const override {
    EmitResult result;
    const PassContext& ctx = r.context;
    const SourceInfo& info = ctx.source;
    spirv::Module emitModule = ctx.module;
    SourceInfo emitInfo = info;
    if (ctx.options.eye.glBinding && ctx.eye.variable) emitInfo.explicitBinding.insert(ctx.module.name(ctx.eye.variable));
    stripAutoAssignedQualifiers(emitModule, emitInfo);
    if (r.target == TargetLanguage::Glsl || r.target == TargetLanguage::Essl) {
      signIntegerBuiltIns(emitModule);
      if (glslOutputVersion(ctx, r.target) < (r.target == TargetLanguage::Essl ? 300 : 130))
        widenLegacyFragmentOutputs(emitModule);
    }
    EmitHints hints = collectHints(emitModule);
    EmittedSource emitted = emitSource(emitModule.encode(), info, r.options, ctx.options.eye.select, hints, r.input.path, diags);
    if (!emitted.ok) return result;  // Failed, with SPIRV-Cross's reason
    result.output = std::move(emitted.text);
    if (r.target != TargetLanguage::Msl) {
      CompileCheck check;
      check.text = result.output;
      check.language = r.target == TargetLanguage::Hlsl ? SourceLanguage::Hlsl : SourceLanguage::Glsl;
      check.stage = info.stage;
      check.entryPoint = r.target == TargetLanguage::Hlsl ? (info.entryPoint.empty() ? "main" : info.entryPoint) : "main";
      check.vulkanSemantics = emitted.vulkanSemantics;
      check.failure = "the emitted " + std::string(targetWord(r.target)) +
                      " does not compile; nothing was written (the target cannot express this shader as it is)";
      result.checks.push_back(std::move(check));
      result.reportsVerified = true;
    }
    result.status = EmitResult::Emitted;
    return result;
  }
};

}  // namespace

std::unique_ptr<BackEndRoute> createReemitRoute() { return std::make_unique<ReemitRoute>(); }

}  // namespace stereoshift
