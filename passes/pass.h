// The pass interface and what passes share: the context (the module, its analysis manager, the run
// record the passes fill) and the eye parameters. The eye parameters are declared and loaded by
// eye_param_emitter.h and the shift emitted by shift_emitter.h, which every pass uses alike (so the
// position and its halo copies are shifted by exactly the same instruction sequence, bit for bit).
#pragma once

#include "passes/analysis_manager.h"
#include "core/diagnostics.h"
#include "passes/ir/module.h"
#include "passes/next_stage_facts.h"
#include "passes/pass_options.h"
#include "passes/run_record.h"
#include "core/shader.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

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
  kProjScaleX,   // the projection's x scale P00, for view-ray deferred lighting without a projection
  kEyeParamCount
};

// The value a parameter has until the application sets it (a specialization constant's default):
// mono, eyeSign 0, convergence 1. Generated shaders that declare the parameters use the same.
float eyeParamDefaultValue(int which);

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

// What the back end will write, as far as a pass must know it: whether `precise` exists there, how
// a single-pass mode can route the eye (language and version: unresolved as asked for, Auto the
// input's own language), and which kinds of edit the output can carry. The driver decides the last
// from the back end's routes before the passes run; a pass asks it, never which route that is.
struct PassOutput {
  TargetLanguage language = TargetLanguage::Auto;
  std::optional<int> version;
  EditSet carries = kAllEdits;
  // When not every kind: the output that cannot carry the rest, in the user's words, for the message
  // of a pass whose edit would be lost ("HLSL hull shaders cannot be re-emitted as HLSL").
  std::string limitedBecause;
  bool canCarry(EditKind kind) const { return hasEdit(carries, kind); }
};

struct PassContext {
  PassContext(spirv::Module& module, const PassOptions& options, const SourceInfo& source, Diagnostics& diags,
              std::string file, AnalysisManager& analyses)
      : module(module), options(options), source(source), diags(diags), file(std::move(file)), analyses(analyses) {}

  spirv::Module& module;
  const PassOptions& options;
  const SourceInfo& source;
  Diagnostics& diags;
  std::string file;
  // The analyses of `module` (computed on first request; the pass manager drops those a pass that
  // changed the module does not preserve).
  AnalysisManager& analyses;
  // What the run did and found: the pass manager records each pass's status, the passes their facts.
  RunRecord record;
  PassOutput output;
  // The module as the front end made it (null for SPIR-V input), so --validate-each blames a pass
  // only for validation errors the front end's module did not already have (see validateSpirv).
  const std::vector<uint32_t>* frontEndSpirv = nullptr;

  // Filled by clip-position-detection.
  Classification classification = Classification::NoPositionOutput;
  // Whether the stereo-shift (and halo) passes shift the clip position: set by detection for a
  // perspective last stage, and by hud-at-depth for a 2D shader it places at depth.
  bool shiftPosition = false;
  // Filled by eye-params (or any pass that declared the parameters: ensureEyeParams).
  EyeParams eye;
  bool eyeDeclared = false;
  // Set by the driver for the last pre-rasterization stage of a pipeline: how the next stage uses
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
std::unique_ptr<Pass> createSinglePassStereoPass();

// Whether the module declares eyeSign next to separation (by the configured names): an earlier
// stereoshift run or the application itself made it stereo already, and shifting or fixing it
// again would double the parallax. Before this run injects anything, that is; see eyeDeclared.
bool carriesEyeParameters(const PassContext& context);

// Why the shader is stereo already ("already carries ...", "reads ..."), or "" when it is not: it carries the eye parameters (above), or it
// reads the view index (BuiltIn ViewIndex: gl_ViewIndex, gl_ViewID_OVR, SV_ViewID), so each eye is a
// view of a multiview draw and its positions or matrices are picked per view already. Shifting it, or
// giving it a per-eye camera, would double the parallax.
std::string alreadyStereoReason(const PassContext& context);

// Whether bindings count per register class (D3D-style HLSL) rather than in one space (GLSL, SPIR-V,
// HLSL with [[vk::binding]]).
bool perClassRegisters(const SourceInfo& source);
// The highest Binding among the variables of descriptor set `set`. With `constantBuffersOnly` only
// Uniform-storage blocks count: HLSL registers are per class (b, t, s, u), glslang maps each class
// onto the same binding numbers.
std::optional<uint32_t> highestBinding(const spirv::Module& module, uint32_t set, bool constantBuffersOnly);

}  // namespace stereoshift
