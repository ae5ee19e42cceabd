// This turns the per-eye corrections the passes found in an HLSL pixel shader that comes back as
// HLSL into text: the deferred pass's text fixes (an unprojection through cbuffer rows, placed by
// source line, and the view-space x rebuilt per component: RunRecord::deferred.textFixes,
// rayTextFixes) spliced into the original file
// (hlsl_splice/pixel.cpp) with 3Dmigoto's StereoParams. What only the IR carries (a fix the pass
// made in the module) is not this route's: it declines, and the re-emit takes the stage.
#include "transpiler/backend/splice_routes.h"

#include "passes/shift_emitter.h"
#include "transpiler/backend/hlsl_splice.h"

#include <algorithm>

namespace stereoshift {

namespace {

// The stereo pixel shader re-compiled as a driver reads it: its own text, entry point and #includes.
CompileCheck pixelShaderCheck(const EmitRequest& r, const std::string& text, const std::string& entryPoint) {
  CompileCheck check;
  check.text = text;
  check.language = SourceLanguage::Hlsl;
  check.stage = Stage::Fragment;
  check.entryPoint = entryPoint;
  check.vulkanSemantics = true;
  check.blankEffects = true;
  check.includeFrom = r.input.path;
  check.failure = "the stereo HLSL of pixel shader '" + entryPoint + "' does not compile";
  return check;
}

class HlslPixelSpliceRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "hlsl-pixel-splice"; }
  bool takesStereoParamsTexture() const override { return true; }
  // The module is only the analysis: the output is the input's text.
  bool needsValidModule() const override { return false; }

  RouteDecision accepts(const EmitRequest& r) const override {
    const SourceInfo& info = r.context.source;
    const DeferredFacts& deferred = r.context.record.deferred;
    if (info.language != SourceLanguage::Hlsl || r.target != TargetLanguage::Hlsl || info.stage != Stage::Fragment ||
        (deferred.textFixes.empty() && deferred.rayTextFixes.empty() && deferred.interpolatedRayTextFixes.empty()))
      return RouteDecision::decline("not an HLSL pixel shader with corrections for its text");
    if (!r.context.record.passesWithEditsBeyond(editSet(EditKind::UnprojectionCorrection)).empty() ||
        deferred.fixed.size() != deferred.textFixes.size() + deferred.rayTextFixes.size() +
                                     deferred.cameraTextFixes.size() + deferred.reprojectionTextFixes.size() +
                                     deferred.interpolatedRayTextFixes.size())
      return RouteDecision::decline("a pass changed what only the IR carries besides the text corrections", true);
    return RouteDecision::accept();
  }

  EmitResult emit(const EmitRequest& r, EmitFacts& facts, Diagnostics& diags) const override {
    EmitResult result;
    const SourceInfo& info = r.context.source;
    HlslSpliceResult spliced = splicePixelCorrections(r.input.contents, r.context.record.deferred, info.entryPoint);
    if (!spliced.ok) {
      // The shader is fine in mono, and was copied before it could be corrected: a correction the
      // text cannot carry leaves it as it is, said where (a person can place it by hand), never
      // loses it from a tree conversion.
      diags.add(Diagnostic{Severity::Warning, r.input.path, spliced.line, spliced.column,
                           spliced.error + "; the pixel shader is copied unchanged (mono), for a person to correct"});
      result.output = r.input.contents;
      result.copied = true;
      facts.route = name();
      // The deferred pass's entries say what was found; the note says none of it was written.
      facts.notes.push_back("not corrected: " + spliced.error + " (line " + std::to_string(spliced.line) +
                            "); the corrections listed under deferred-unprojection were not written");
      result.status = EmitResult::Emitted;
      return result;
    }
    result.output = std::move(spliced.text);
    facts.route = name();
    facts.spliceSites = spliced.sites;
    result.checks.push_back(pixelShaderCheck(r, result.output, info.entryPoint));
    result.reportsVerified = r.options.verify;
    result.status = EmitResult::Emitted;
    return result;
  }
};

// An HLSL shader kept as HLSL that gets no shift but whose position rebuild the deferred pass
// fixed in the module (a lighting pixel shader of an engine, not a dump): the fix written into its
// own text (`mul(InvM, ...)` wrapped in a per-eye helper) instead of SPIRV-Cross's re-emit.
class HlslUnprojectionSpliceRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "hlsl-pixel-source-splice"; }

  RouteDecision accepts(const EmitRequest& r) const override {
    const PassContext& ctx = r.context;
    const DeferredFacts& deferred = ctx.record.deferred;
    if (ctx.source.language != SourceLanguage::Hlsl || r.target != TargetLanguage::Hlsl ||
        ctx.source.stage != Stage::Fragment || !ctx.record.madeEdit(EditKind::UnprojectionCorrection))
      return RouteDecision::decline("not an HLSL pixel shader whose unprojection was fixed");
    if (r.options.eyeFrom3DMigoto || ctx.eye.source != EyeSource::UniformBlock)
      return RouteDecision::decline("the eye parameters are not a cbuffer the splice declares");
    if (!ctx.record.passesWithEditsBeyond(EditKind::EyeParameters | EditKind::UnprojectionCorrection).empty() ||
        !deferred.unprojectionTextMissing.empty() || deferred.unprojectionTexts.empty())
      return RouteDecision::decline(
          "HLSL pixel shader re-emitted by SPIRV-Cross instead of spliced into its own text: the splice cannot write " +
              (deferred.unprojectionTextMissing.empty() ? std::string("what the passes changed") : deferred.unprojectionTextMissing),
          true);
    return RouteDecision::accept();
  }

  EmitResult emit(const EmitRequest& r, EmitFacts& facts, Diagnostics&) const override {
    EmitResult result;
    const PassContext& ctx = r.context;
    const spirv::Module& module = ctx.module;
    HlslUnprojectionOptions options;
    options.cbufferName = module.name(module.pointeeType(module.definition(ctx.eye.variable)->typeId));
    options.cbufferRegister = module.decorationValue(ctx.eye.variable, spv::DecorationBinding).value_or(0);
    ShiftSpec spec = shiftSpec(ctx);
    options.eyeSignName = spec.eyeSignName;
    options.separationName = spec.separationName;
    options.convergenceName = spec.convergenceName;
    for (const UnprojectionText& u : ctx.record.deferred.unprojectionTexts) {
      auto same = std::find_if(options.wraps.begin(), options.wraps.end(),
                               [&](const HlslUnprojectionOptions::Wrap& w) { return w.matrix == u.matrix; });
      if (same != options.wraps.end()) {
        ++same->products;
        continue;
      }
      std::string function = "stereoshift_unproject_" + u.matrix;
      std::replace(function.begin(), function.end(), '.', '_');
      options.wraps.push_back({u.matrix, function, 1});
    }
    HlslSpliceResult spliced = spliceHlslUnprojections(r.input.contents, options);
    if (!spliced.ok) {
      result.status = EmitResult::Declined;
      result.declinedBecause =
          "HLSL pixel shader re-emitted by SPIRV-Cross instead of spliced into its own text: " + spliced.error;
      return result;
    }
    result.output = std::move(spliced.text);
    facts.route = name();
    facts.spliceSites = spliced.sites;
    result.checks.push_back(pixelShaderCheck(r, result.output, ctx.source.entryPoint));
    result.declineIfChecksFail = true;
    result.reportsVerified = r.options.verify;
    result.status = EmitResult::Emitted;
    return result;
  }
};

}  // namespace

std::unique_ptr<BackEndRoute> createHlslPixelSpliceRoute() { return std::make_unique<HlslPixelSpliceRoute>(); }
std::unique_ptr<BackEndRoute> createHlslUnprojectionSpliceRoute() {
  return std::make_unique<HlslUnprojectionSpliceRoute>();
}

}  // namespace stereoshift
