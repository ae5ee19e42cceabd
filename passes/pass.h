// The pass interface and what passes share: the clip-position analysis, the eye parameters, and
// the one piece of code that emits the stereo shift (so the position and its halo copies are shifted
// by exactly the same instruction sequence, bit for bit).
#pragma once

#include "passes/diagnostics.h"
#include "passes/ir/module.h"
#include "passes/next_stage_facts.h"
#include "passes/shader.h"
#include "passes/shift_emitter.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

enum class PassResult { Unchanged, Changed, Failed };
const char* toString(PassResult result);

// Where the clip position lives: an Output variable, or a member of an Output block.
struct ClipPosition {
  uint32_t variable = 0;
  bool isMember = false;
  uint32_t member = 0;        // member index in the block, when isMember
  bool arrayed = false;       // per-vertex arrays (tessellation control, mesh): not shifted here
  std::string description;    // e.g. "gl_PerVertex.gl_Position"
};

// Why a shader gets (or does not get) the shift; reported per shader.
enum class Classification {
  Perspective,      // last pre-rasterization stage writing a clip position: shifted
  ConstantW1,       // every write of the position has the literal w = 1.0: 2D, nothing injected
  AlreadyStereo,    // already carries the eye parameters: never shifted twice
  Intermediate,     // pre-rasterization stage followed by a later one in its pipeline
  NoPositionStage,  // tessellation control, fragment, compute, task: no clip position to shift
  NoPositionOutput, // a pre-rasterization stage that writes no clip position
};
const char* toString(Classification c);

// The eye parameters by index. The injected block's layout is fixed by index (member i at byte
// offset 4*i from the first), so every shader of an application agrees on it whichever prefix it
// declares: the shift needs the first three, HUD-at-depth four, a per-eye camera offset all seven.
enum EyeParam : int {
  kEyeSign = 0,
  kSeparation,
  kConvergence,
  kHudDepth,     // eye depth of a 2D element placed at depth (HUD-at-depth)
  kEyeOffsetX,   // world-space offset of this eye's centre from the mono camera (per-eye view
  kEyeOffsetY,   // vectors when the shader has no matrix to derive it from)
  kEyeOffsetZ,
  kEyeParamCount
};

// Ids of the injected eye parameters.
struct EyeParams {
  EyeSource source = EyeSource::UniformBlock;
  int declared = 0;                // how many of the EyeParam values are declared (a prefix)
  uint32_t variable = 0;           // block / push-constant variable (UniformBlock, PushConstant)
  uint32_t blockType = 0;          // its struct type
  uint32_t firstMember = 0;        // index of eyeSign in that block
  uint32_t firstOffset = 0;        // byte offset of eyeSign in that block
  uint32_t looseVariables[kEyeParamCount] = {}; // LooseUniforms
  uint32_t specConstants[kEyeParamCount] = {};  // SpecConstant
  std::string names[kEyeParamCount];            // final names after clash resolution
};

struct PassContext {
  spirv::Module& module;
  const TranspileOptions& options;
  const SourceInfo& source;
  Diagnostics& diags;
  std::string file;
  nlohmann::json& report;  // passes add what they did under report["passes"][name()]

  // Filled by clip-position-detection.
  std::vector<ClipPosition> positions;
  Classification classification = Classification::NoPositionOutput;
  // Whether the stereo-shift (and halo) passes shift the clip position: set by detection for a
  // perspective last stage, and by hud-at-depth for a 2D shader it places at depth.
  bool shiftPosition = false;
  // Filled by eye-params.
  EyeParams eye;
  bool eyeDeclared = false;
  // See foldedCopy().
  std::optional<spirv::Module> folded;
  bool foldTried = false;
  // Set by transpilePipeline() for the last pre-rasterization stage: how the fragment stage uses
  // each of its inputs (per-eye-view decides per output from it). Null in single-shader mode.
  const NextStageFacts* nextStage = nullptr;
};

class Pass {
 public:
  virtual ~Pass() = default;
  virtual const char* name() const = 0;  // equal to its --pass flag
  virtual PassResult run(PassContext& context) = 0;
};

std::unique_ptr<Pass> createClipPositionDetectionPass();
std::unique_ptr<Pass> createEyeParamsPass();
std::unique_ptr<Pass> createStereoShiftPass();
std::unique_ptr<Pass> createHaloPass();
std::unique_ptr<Pass> createHudAtDepthPass();
std::unique_ptr<Pass> createPerEyeViewPass();
std::unique_ptr<Pass> createDeferredUnprojectionPass();

// Declares the eye parameters 0..count-1 (see EyeParam) if they are not declared yet, or extends
// the declared ones up to `count`. Any pass that needs them calls this; the eye-params pass does so
// for shaders that get the shift. False (with an error in ctx.diags) when they cannot be declared.
bool ensureEyeParams(PassContext& context, int count);

// An inlined, constant-folded throw-away copy of the module (SPIRV-Tools' performance passes), made
// once per shader on first request and shared by the analyses that need to see through helper
// functions and structs. Only used to answer questions, never emitted; global ids (variables) are
// the module's own. Null when the optimizer cannot process the module.
const spirv::Module* foldedCopy(PassContext& context);

// Whether the module declares eyeSign next to separation (by the configured names): an earlier
// stereoshift run or the application itself made it stereo already, and shifting or fixing it
// again would double the parallax. Before this run injects anything, that is; see eyeDeclared.
bool carriesEyeParameters(const PassContext& context);

// The highest Binding among the variables of descriptor set `set`. With `constantBuffersOnly` only
// Uniform-storage blocks count: HLSL registers are per class (b, t, s, u), glslang maps each class
// onto the same binding numbers.
std::optional<uint32_t> highestBinding(const spirv::Module& module, uint32_t set, bool constantBuffersOnly);

}  // namespace stereoshift
