// The pass interface and what passes share: the context with its cached analyses (clip positions,
// the folded copy) and the eye parameters. The shift itself is emitted by shift_emitter.h (so the
// position and its halo copies are shifted by exactly the same instruction sequence, bit for bit).
#pragma once

#include "passes/analysis/clip_positions.h"
#include "passes/diagnostics.h"
#include "passes/ir/module.h"
#include "passes/next_stage_facts.h"
#include "passes/shader.h"
#include "passes/shift_emitter.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <vector>
#include <string>
#include <vector>

namespace stereoshift {

enum class PassResult { Unchanged, Changed, Failed };
const char* toString(PassResult result);

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

// The analyses a context computes on first request and keeps while they hold (SPIRV-Tools'
// IRContext analyses, LLVM's analysis manager in miniature). A pass's registry entry declares which
// it needs and which survive it; after a pass that changed the module the pass manager drops the
// others, so the next request recomputes them on the module as it is then.
enum Analysis : unsigned {
  kClipPositionAnalysis = 1u << 0,  // clipPositions(): the position outputs, their pointers, mono values
  kFoldedCopyAnalysis = 1u << 1,    // foldedCopy(): the inlined, constant-folded copy
};
using AnalysisSet = unsigned;
constexpr AnalysisSet kNoAnalyses = 0;
constexpr AnalysisSet kAllAnalyses = kClipPositionAnalysis | kFoldedCopyAnalysis;
const char* analysisName(Analysis analysis);

struct PassContext {
  PassContext(spirv::Module& module, const TranspileOptions& options, const SourceInfo& source, Diagnostics& diags,
              std::string file, nlohmann::json& report)
      : module(module), options(options), source(source), diags(diags), file(std::move(file)), report(report) {}

  spirv::Module& module;
  const TranspileOptions& options;
  const SourceInfo& source;
  Diagnostics& diags;
  std::string file;
  nlohmann::json& report;  // passes add what they did under report["passes"][name()]
  // The module as the front end made it (null for SPIR-V input), so --validate-each blames a pass
  // only for validation errors the front end's module did not already have (see validateSpirv).
  const std::vector<uint32_t>* frontEndSpirv = nullptr;

  // The clip-position outputs: clipPositions(*this).outputs(), kept here each time the analysis is
  // computed for the passes that read them from the context (no pass adds or removes an output).
  std::vector<ClipPosition> positions;
  // Filled by clip-position-detection.
  Classification classification = Classification::NoPositionOutput;
  // Whether the stereo-shift (and halo) passes shift the clip position: set by detection for a
  // perspective last stage, and by hud-at-depth for a 2D shader it places at depth.
  bool shiftPosition = false;
  // Filled by eye-params.
  EyeParams eye;
  bool eyeDeclared = false;
  // Set by transpilePipeline() for the last pre-rasterization stage: how the fragment stage uses
  // each of its inputs (per-eye-view decides per output from it). Null in single-shader mode.
  const NextStageFacts* nextStage = nullptr;

  // ---- the analysis cache (read through clipPositions() and foldedCopy()) ----
  std::optional<ClipPositionAnalysis> clipPositionCache;
  // See foldedCopy(): the copy, and whether making it was tried (it stays null when the optimizer
  // cannot process the module). A pipeline hands both on from an earlier analysis of the stage.
  std::optional<spirv::Module> folded;
  bool foldTried = false;

  // Drops every cached analysis not in `kept` (after a pass changed the module).
  void invalidateAnalyses(AnalysisSet kept);
  // The analyses cached right now (for the tests and the pass manager's checks).
  AnalysisSet cachedAnalyses() const;
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

// eyeSign in the single-pass modes (EyeSelect ViewIndex / InstanceIndex): appends the instructions
// that derive it per view or instance (exactly -1.0 or +1.0) and returns the float id; see
// single_pass_stereo_pass.cpp. emitLoadEyeParam calls it for eyeSign in those modes.
uint32_t emitDerivedEyeSign(PassContext& context, std::vector<spirv::Instruction>& out);

// The lowest OpenGL GLSL version a single-pass mode needs for this stage of an OpenGL (not Vulkan,
// not ES) GLSL shader kept in GLSL, when the shader's own version is below it and no --target-version
// was given (the output is then raised to it: desktop GLSL links stages of different versions);
// nullopt otherwise, and for a shader using compatibility built-ins (SourceInfo; a raise would turn gl_Vertex,
// gl_ModelViewProjectionMatrix, ... into stereoshift_* inputs and uniforms the application does not
// set: that takes an explicit --target-version). `why` receives the reason. See
// single_pass_stereo_pass.cpp.
std::optional<int> singlePassRaisedGlslVersion(const SourceInfo& source, const TranspileOptions& options,
                                               std::string* why);

// Declares the eye parameters 0..count-1 (see EyeParam) if they are not declared yet, or extends
// the declared ones up to `count`. Any pass that needs them calls this; the eye-params pass does so
// for shaders that get the shift. False (with an error in ctx.diags) when they cannot be declared.
bool ensureEyeParams(PassContext& context, int count);

// An inlined, constant-folded throw-away copy of the module (SPIRV-Tools' performance passes), made
// once per shader on first request and shared by the analyses that need to see through helper
// functions and structs. Only used to answer questions, never emitted; global ids (variables) are
// the module's own. Null when the optimizer cannot process the module.
const spirv::Module* foldedCopy(PassContext& context);

// The clip-position analysis of the module as it is now: computed on first request, cached until a
// pass that changed the module does not preserve it (see Analysis).
const ClipPositionAnalysis& clipPositions(PassContext& context);

// Whether the module declares eyeSign next to separation (by the configured names): an earlier
// stereoshift run or the application itself made it stereo already, and shifting or fixing it
// again would double the parallax. Before this run injects anything, that is; see eyeDeclared.
bool carriesEyeParameters(const PassContext& context);

// Why the shader is stereo already ("already carries ...", "reads ..."), or "" when it is not: it carries the eye parameters (above), or it
// reads the view index (BuiltIn ViewIndex: gl_ViewIndex, gl_ViewID_OVR, SV_ViewID), so each eye is a
// view of a multiview draw and its positions or matrices are picked per view already. Shifting it, or
// giving it a per-eye camera, would double the parallax.
std::string alreadyStereoReason(const PassContext& context);

// The highest Binding among the variables of descriptor set `set`. With `constantBuffersOnly` only
// Uniform-storage blocks count: HLSL registers are per class (b, t, s, u), glslang maps each class
// onto the same binding numbers.
// Whether bindings count per register class (D3D-style HLSL) rather than in one space (GLSL, SPIR-V,
// HLSL with [[vk::binding]]).
bool perClassRegisters(const SourceInfo& source);
std::optional<uint32_t> highestBinding(const spirv::Module& module, uint32_t set, bool constantBuffersOnly);

}  // namespace stereoshift
