// The pass registry: one entry per pass, in pipeline order. Everything that lists passes is made from
// it: the pipeline the pass manager runs, `--pass` validation and its --help text, what `--pass X`
// pulls in, the single-pass test fixture. A new pass is one factory in its own file plus one entry
// in pass_registry.cpp, placed where its ordering reason says.
#pragma once

#include "passes/pass.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stereoshift {

struct PassInfo {
  const char* name;             // equal to the pass's name() and its --pass flag
  std::unique_ptr<Pass> (*create)();
  const char* description;      // one line, for --help
  const char* enabledBy;        // the option that turns it on (or off)
  const char* whyHere;          // why the pipeline runs it at this position
  std::vector<const char*> requiredPasses;  // must have run first (the pass reads what they decide)
  AnalysisSet requiredAnalyses; // cached analyses it reads (computed on the first request)
  AnalysisSet preservedAnalyses;  // still valid after it changed the module
  EditSet edits = kNoEdits;     // what its change to the module is, for the routes (none: analysis only)
  // An opt-in mode's pass: whether a full pipeline with these options runs it (null: always).
  bool (*runsFor)(const PassOptions& options) = nullptr;
};

// Each pass's entry, defined in the pass's own file beside its code (what it does, why it runs
// where it does, what it needs, what its change preserves, what kind of edit it is); in pipeline order.
PassInfo clipPositionDetectionPassInfo();
PassInfo hudAtDepthPassInfo();
PassInfo singlePassStereoPassInfo();
PassInfo eyeParamsPassInfo();
PassInfo haloPassInfo();
PassInfo stereoShiftPassInfo();
PassInfo perEyeViewPassInfo();
PassInfo deferredUnprojectionPassInfo();

// What survives a pass that only adds declarations or rewrites stores to outputs other than the
// position: the clip position's pointers and values, the folded copy's answers about the
// application's own values, how the stage uses its inputs. Not the value-flow and value-number
// indexes, which point into the instruction lists the change moved.
constexpr AnalysisSet kKeptByDeclarations = kClipPositionAnalysis | kFoldedCopyAnalysis | kStageInputAnalysis;

// Every pass, in the order the pipeline runs them.
const std::vector<PassInfo>& passRegistry();
// Whether the full pipeline runs `info` for `options`: every pass runs (and reports) always, except
// the opt-in modes' own passes, which a conversion without them never shows: single-pass-stereo
// runs only for --eye-source multiview|instanced.
bool passRunsFor(const PassInfo& info, const PassOptions& options);
// The entry named `name`, or null.
const PassInfo* findPass(std::string_view name);
// "clip-position-detection, hud-at-depth, ...": the valid --pass names, in pipeline order.
std::string passNameList();
// The --help text of --pass: the names on the first line, then one line per pass (what it does, the
// option that turns it on, what it requires).
std::string passHelpText();
// nullopt when every name is a pass, else the error for the first unknown one (listing the valid names).
std::optional<std::string> checkPassNames(const std::vector<std::string>& names);

// The passes `--pass` runs for `named`: those, and transitively what they require, in pipeline
// order. `requiredBy` (parallel to the result) names, for a pass only pulled in, the named pass
// that needed it first; empty for a named pass. Every name must be a registered one.
std::vector<const PassInfo*> selectPasses(const std::vector<std::string>& named, std::vector<std::string>* requiredBy);

}  // namespace stereoshift
