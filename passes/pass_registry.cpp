// The registry's entries (see pass_registry.h). Their order is the pipeline's, and each entry's
// whyHere says what fixes its position.
#include "passes/pass_registry.h"

#include <algorithm>

namespace stereoshift {

namespace {

// What survives a pass that only adds declarations or rewrites stores to outputs other than the
// position: the clip position's pointers and values, the folded copy's answers about the
// application's own values, how the stage uses its inputs. Not the value-flow and value-number
// indexes, which point into the instruction lists the change moved.
constexpr AnalysisSet kKeptByDeclarations = kClipPositionAnalysis | kFoldedCopyAnalysis | kStageInputAnalysis;

}  // namespace

const std::vector<PassInfo>& passRegistry() {
  static const std::vector<PassInfo> registry = {
      {"clip-position-detection", createClipPositionDetectionPass,
       "classifies the shader (perspective, 2D, already stereo, ...) and finds its clip-position outputs",
       "always",
       "analysis only, first: every geometry pass below does nothing unless it found a perspective last stage",
       {}, kClipPositionAnalysis | kFoldedCopyAnalysis, kAllAnalyses, kNoEdits},
      // Placing at depth scales the stored position; the folded copy still answers what later passes
      // ask of it (which outputs copy the position the application computed), so it is kept.
      {"hud-at-depth", createHudAtDepthPass,
       "places a proven-2D shader (w = 1) at the eye depth hudDepth, so it gets the shift",
       "--hud-at-depth (off by default)",
       "turns a 2D position into one at depth, which then needs the shift like any perspective position: "
       "before eye-params, halo and stereo-shift",
       {"clip-position-detection"}, kClipPositionAnalysis, kFoldedCopyAnalysis,
       static_cast<EditSet>(EditKind::PositionAtDepth)},
      // Rewrites reads of the instance index and adds outputs other than the position: the position's
      // pointers and values stay, the folded copy no longer matches the module.
      {"single-pass-stereo", createSinglePassStereoPass,
       "draws both eyes in one pass: eyeSign from the view index (multiview) or the instance index (instanced; "
       "the original instance given to the shader, the eye handed on to the rasterizing stage and routed to the "
       "layer or viewport)",
       "--eye-source multiview | instanced",
       "after detection (it routes 2D vertex shaders too) and before eye-params and the shift, so the instance "
       "reads it rewrites are only the application's own",
       {"clip-position-detection"}, kNoAnalyses, kClipPositionAnalysis, static_cast<EditSet>(EditKind::SinglePassEye)},
      // Adds a declaration only: no output, no pointer to the position, no application value changes
      // (but new globals: the value-flow and value-number indexes point into what moved).
      {"eye-params", createEyeParamsPass,
       "declares eyeSign, separation and convergence in a shader that gets the shift",
       "always (--eye-source chooses how)",
       "the shift and halo code load the parameters it declares",
       {"clip-position-detection"}, kNoAnalyses, kKeptByDeclarations, static_cast<EditSet>(EditKind::EyeParameters)},
      // Rewrites stores to other outputs only: the position's pointers and values stay as they were.
      {"halo", createHaloPass,
       "shifts outputs computed from the clip position (copies, screen UVs) like the position itself",
       "on (--no-halo turns it off)",
       "before the shift, while the only loads of the position are the application's own, so it sees "
       "exactly the values the application derived its outputs from",
       {"clip-position-detection", "eye-params"}, kClipPositionAnalysis | kFoldedCopyAnalysis | kValueNumberAnalysis,
       kKeptByDeclarations, static_cast<EditSet>(EditKind::DerivedOutputShift)},
      // Loads the position and adds chains to it: new pointers and values, the analysis is stale.
      {"stereo-shift", createStereoShiftPass,
       "shifts the final clip position by eyeSign*separation*(w - convergence) at every return / emit",
       "always (--shift-form, --no-cutoff, --fused-shift, --compensated-shift: how)",
       "after halo; it guards and shifts the position where it is final",
       {"clip-position-detection", "eye-params"}, kClipPositionAnalysis, kFoldedCopyAnalysis,
       static_cast<EditSet>(EditKind::PositionShift)},
      {"per-eye-view", createPerEyeViewPass,
       "uses the per-eye camera position in view vectors that offset texture coordinates",
       "on (--no-per-eye-view turns it off, --per-eye-specular extends it)",
       "independent of the shift (it also runs on fragment shaders) and declares the eye parameters it "
       "needs itself; it reads detection's classification and clip positions",
       {"clip-position-detection"}, kClipPositionAnalysis | kFoldedCopyAnalysis, kNoAnalyses,
       // The eye parameters it declares for itself are part of its edit.
       static_cast<EditSet>(EditKind::PerEyeCamera)},
      {"deferred-unprojection", createDeferredUnprojectionPass,
       "makes position reconstruction in deferred lighting per eye: InvM * vec4(ndc, depth, 1) and viewRay * depth",
       "on (--no-deferred-unprojection turns it off)",
       "independent of the shift, like per-eye-view; last, as it needs nothing the others decide",
       {}, kValueFlowAnalysis, kNoAnalyses, static_cast<EditSet>(EditKind::UnprojectionCorrection)},
  };
  return registry;
}

bool passRunsFor(const PassInfo& info, const PassOptions& options) {
  if (std::string_view(info.name) == "single-pass-stereo") return options.eye.select != EyeSelect::Parameter;
  return true;
}

const PassInfo* findPass(std::string_view name) {
  for (const auto& info : passRegistry())
    if (name == info.name) return &info;
  return nullptr;
}

std::string passNameList() {
  std::string list;
  for (const auto& info : passRegistry()) list += (list.empty() ? "" : ", ") + std::string(info.name);
  return list;
}

std::string passHelpText() {
  std::string text = "Run only this pass and the passes it requires (repeatable), in pipeline order: " + passNameList();
  for (const auto& info : passRegistry()) {
    text += "\n  " + std::string(info.name) + ": " + info.description + " [" + info.enabledBy + "]";
    if (!info.requiredPasses.empty()) {
      text += " (requires ";
      for (size_t i = 0; i < info.requiredPasses.size(); ++i) text += (i ? ", " : "") + std::string(info.requiredPasses[i]);
      text += ")";
    }
  }
  return text;
}

std::optional<std::string> checkPassNames(const std::vector<std::string>& names) {
  for (const auto& name : names)
    if (!findPass(name)) return "unknown --pass '" + name + "' (valid: " + passNameList() + ")";
  return std::nullopt;
}

std::vector<const PassInfo*> selectPasses(const std::vector<std::string>& named, std::vector<std::string>* requiredBy) {
  const auto& registry = passRegistry();
  // Per registry entry: whether it runs, and for one only pulled in, the named pass that needed it.
  std::vector<bool> selected(registry.size(), false);
  std::vector<std::string> requester(registry.size());
  auto indexOf = [&](std::string_view name) {
    for (size_t i = 0; i < registry.size(); ++i)
      if (name == registry[i].name) return i;
    return registry.size();
  };
  // Named passes first (so a pass both named and required counts as named), then their
  // requirements, depth first; each pass is the requirement of the first named pass that needs it.
  std::vector<size_t> roots;
  for (const auto& name : named)
    if (size_t i = indexOf(name); i < registry.size() && !selected[i]) {
      selected[i] = true;
      roots.push_back(i);
    }
  for (size_t root : roots) {
    std::vector<size_t> stack = {root};
    while (!stack.empty()) {
      size_t at = stack.back();
      stack.pop_back();
      for (const char* required : registry[at].requiredPasses) {
        size_t r = indexOf(required);
        if (r == registry.size() || selected[r]) continue;
        selected[r] = true;
        requester[r] = registry[root].name;
        stack.push_back(r);
      }
    }
  }
  std::vector<const PassInfo*> passes;
  if (requiredBy) requiredBy->clear();
  for (size_t i = 0; i < registry.size(); ++i) {
    if (!selected[i]) continue;
    passes.push_back(&registry[i]);
    if (requiredBy) requiredBy->push_back(requester[i]);
  }
  return passes;
}

}  // namespace stereoshift
