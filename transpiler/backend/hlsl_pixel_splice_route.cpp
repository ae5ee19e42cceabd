// This turns the per-eye corrections the passes found in an HLSL pixel shader that comes back as
// HLSL into text: the deferred pass's text fixes (an unprojection through cbuffer rows, placed by
// source line, and the view-space x rebuilt per component: RunRecord::deferred.textFixes,
// rayTextFixes) spliced into the original file
// (hlsl_splice/pixel.cpp) with 3Dmigoto's StereoParams. What only the IR carries (a fix the pass
// made in the module) is not this route's: it declines, and the re-emit takes the stage.
#include "transpiler/backend/splice_routes.h"

#include "transpiler/backend/hlsl_splice.h"

namespace stereoshift {

namespace {

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
        (deferred.textFixes.empty() && deferred.rayTextFixes.empty()))
      return RouteDecision::decline("not an HLSL pixel shader with corrections for its text");
    if (!r.context.record.passesWithEditsBeyond(editSet(EditKind::UnprojectionCorrection)).empty() ||
        deferred.fixed.size() != deferred.textFixes.size() + deferred.rayTextFixes.size() + deferred.cameraTextFixes.size())
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
    CompileCheck check;
    check.text = result.output;
    check.language = SourceLanguage::Hlsl;
    check.stage = Stage::Fragment;
    check.entryPoint = info.entryPoint;
    check.vulkanSemantics = true;
    check.blankEffects = true;
    check.includeFrom = r.input.path;
    check.failure = "the stereo HLSL of pixel shader '" + info.entryPoint + "' does not compile";
    result.checks.push_back(std::move(check));
    result.reportsVerified = r.options.verify;
    result.status = EmitResult::Emitted;
    return result;
  }
};

}  // namespace

std::unique_ptr<BackEndRoute> createHlslPixelSpliceRoute() { return std::make_unique<HlslPixelSpliceRoute>(); }

}  // namespace stereoshift
