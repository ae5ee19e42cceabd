// This turns the passes' decisions for a legacy GLSL vertex shader (ESSL 100, desktop GLSL 110-150)
// into stereo GLSL of the same dialect by the source splice of glsl_splice.h: the passes ran on the
// analysis translation, the shift is written into the user's own text. What the text cannot carry
// (other passes' changes, halo outputs computed from the position) is said as a warning and listed
// in the report's not_carried.
#include "transpiler/backend/splice_routes.h"

#include "passes/shift_emitter.h"
#include "transpiler/backend/glsl_splice.h"

#include <algorithm>
#include <string_view>

namespace stereoshift {

bool takesLegacyGlslRoute(const SourceInfo& info, TargetLanguage target, const BackEndOptions& options) {
  return isLegacyGlslDialect(info) && info.stage == Stage::Vertex && target == (info.es ? TargetLanguage::Essl : TargetLanguage::Glsl) &&
         !options.targetVersion && !options.forceReemit;
}

bool isLegacyGlslDialect(const SourceInfo& info) {
  return info.language == SourceLanguage::Glsl && !info.vulkan && (info.es ? info.version < 300 : info.version < 330);
}

std::string sourceName(const std::string& translated) {
  static constexpr std::string_view kPrefix = "stereoshift_";
  if (translated.starts_with(kPrefix)) return "gl_" + translated.substr(kPrefix.size());
  return translated;
}

namespace {

class LegacyGlslRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "legacy-glsl-source-splice"; }

  RouteDecision accepts(const EmitRequest& r) const override {
    if (!takesLegacyGlslRoute(r.context.source, r.target, r.options))
      return RouteDecision::decline("not a legacy GLSL vertex shader kept in its dialect");
    if (r.context.eye.source != EyeSource::LooseUniforms)
      return RouteDecision::refuse("GLSL below 330 and ESSL 100 keep their own dialect, where the eye parameters are "
                                   "loose uniforms: use --eye-source loose-uniforms (or auto), or choose --target and "
                                   "--target-version");
    return RouteDecision::accept();
  }

  EmitResult emit(const EmitRequest& r, EmitFacts& facts, Diagnostics& diags) const override {
    EmitResult result;
    const PassContext& ctx = r.context;
    const std::string& file = r.input.path;
    GlslSpliceOptions splice;
    static_cast<ShiftSpec&>(splice) = shiftSpec(ctx);
    splice.version = ctx.source.version;
    splice.es = ctx.source.es;
    std::vector<std::string> dropped;
    auto drop = [&](const std::string& what) {
      diags.warning(file, "the legacy GLSL text route cannot carry " + what + "; the output leaves it out");
      dropped.push_back(what);
    };
    if (splice.fused) drop("--fused-shift (GLSL 1xx has no fma: the plain form is used)");
    if (splice.compensated) drop("--compensated-shift (GLSL 1xx has no `precise`: the plain form is used)");
    // The splice renders the eye parameters, the shift and halo copies.
    for (const auto& pass : ctx.record.passesWithEditsBeyond(kGlslSpliceRenders))
      drop("what the " + pass + " pass changed");
    // Halo outputs: exact copies of gl_Position are re-copied after the shift; derived ones read the
    // position through the shift where the analysis says how their one assignment reads it
    // (HaloFacts::DerivedText), else they are left out.
    std::vector<std::string> copies = exactPositionCopies(r.input.contents);
    const HaloFacts& halo = ctx.record.halo;
    if (halo.shiftedOutputs)
      for (const auto& out : *halo.shiftedOutputs) {
        std::string name = sourceName(out);
        auto derived = std::find_if(halo.derivedTexts.begin(), halo.derivedTexts.end(),
                                    [&](const HaloFacts::DerivedText& t) { return t.output == out; });
        if (std::find(copies.begin(), copies.end(), name) != copies.end()) {
          if (std::find(splice.haloCopies.begin(), splice.haloCopies.end(), name) == splice.haloCopies.end())
            splice.haloCopies.push_back(name);
        } else if (derived != halo.derivedTexts.end()) {
          GlslSpliceOptions::DerivedHalo text{sourceName(derived->path), {}};
          for (const auto& position : derived->positionNames) text.positionNames.push_back(sourceName(position));
          splice.derivedHalos.push_back(std::move(text));
        } else {
          drop("the halo fix of output '" + name + "' (derived from the clip position, not a plain copy)");
        }
      }
    GlslSpliceResult spliced = spliceGlslStereo(r.input.contents, splice);
    if (!spliced.ok) {
      diags.error(file, spliced.line, spliced.column, "cannot splice the stereo shift: " + spliced.error);
      return result;
    }
    result.output = std::move(spliced.text);
    facts.route = "glsl-source-splice";
    facts.haloCopies = splice.haloCopies;
    facts.notCarried = dropped;
    // Always re-compiled at the original version, as a driver reads it: an output that does not
    // compile is never written.
    CompileCheck check;
    check.text = result.output;
    check.stage = ctx.source.stage;
    check.legacy = true;
    // A lifted copy's source (frontend/glsl_lift.h): through the front end, which lifts it again.
    check.throughFrontEnd = !ctx.source.liftedBecause.empty() || ctx.source.versionPrepended;
    check.version = ctx.source.version;
    check.es = ctx.source.es;
    check.failure = "the emitted shader does not compile at its original version";
    result.checks.push_back(std::move(check));
    result.reportsVerified = true;
    result.status = EmitResult::Emitted;
    return result;
  }
};

}  // namespace

std::unique_ptr<BackEndRoute> createLegacyGlslRoute() { return std::make_unique<LegacyGlslRoute>(); }

}  // namespace stereoshift
