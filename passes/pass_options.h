// The options the passes read: where the eye parameters come from and what they are called, the
// shift's form and cutoff, the per-eye fixes, and how the pass pipeline runs. The front and back
// ends have options of their own (transpiler/frontend/front_end_options.h,
// transpiler/backend/back_end_options.h); a
// conversion's TranspileOptions is all three.
#pragma once

#include "core/shift_spec.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// Where the eye parameters (eyeSign, separation, convergence) come from.
enum class EyeSource {
  Auto,           // loose uniforms for OpenGL GLSL shaders that use loose uniforms, else UniformBlock
  UniformBlock,   // uniform block / cbuffer `StereoParams`
  PushConstant,   // members of the push-constant block (merged into an existing one)
  SpecConstant,   // specialization constants: a build can bake left and right variants
  LooseUniforms,  // OpenGL default-block uniforms
};

// Where eyeSign comes from. `Parameter`: one of the EyeSource kinds above (two passes, the
// application changes it between them). The single-pass modes derive it per vertex instead, so
// both eyes are drawn in one pass (separation and convergence stay where EyeSource puts them):
// `ViewIndex`: multiview (view 0 left, view 1 right); `InstanceIndex`: instanced stereo (the low bit
// of the instance index, the eye written to the render-target layer or viewport index).
enum class EyeSelect { Parameter, ViewIndex, InstanceIndex };
// Where instanced stereo sends each eye: a layer of a layered target, or a viewport (side by side).
enum class EyeRoute { Layer, Viewport };


struct EyeParamOptions {
  EyeSource source = EyeSource::Auto;
  std::string blockName = "StereoParams";
  std::string instanceName = "stereo";
  std::string eyeSignName = "eyeSign";
  std::string separationName = "separation";
  std::string convergenceName = "convergence";
  std::string hudDepthName = "hudDepth";        // declared only with --hud-at-depth
  std::string eyeOffsetXName = "eyeOffsetX";    // declared only for per-eye view vectors that have
  std::string eyeOffsetYName = "eyeOffsetY";    // no matrix to derive the eye centre from
  std::string eyeOffsetZName = "eyeOffsetZ";
  std::string projScaleXName = "projScaleX";    // declared only for view rays with no projection at hand
  std::optional<uint32_t> descriptorSet;  // default 0
  std::optional<uint32_t> binding;        // default: first binding unused in the set
  std::optional<uint32_t> hlslRegister;   // cbuffer register b<N>; default: first unused
  std::optional<uint32_t> glBinding;      // OpenGL uniform-block binding; default: none (by name)
  uint32_t specIdBase = 100;              // SpecId of eyeSign; separation and convergence follow
  // Single-pass stereo (--eye-source multiview|instanced): see EyeSelect.
  EyeSelect select = EyeSelect::Parameter;
  bool swapEyes = false;                  // view / instance eye 0 is the right eye (+1)
  EyeRoute route = EyeRoute::Layer;       // instanced: --eye-route layer|viewport
  std::string eyeVaryingName = "stereoEye";  // instanced: the flat varying that hands the eye on
  uint32_t eyeVaryingLocation = 15;       // its location (15: the last one every Vulkan device has)
};

struct PassOptions {
  EyeParamOptions eye;
  CutoffMode cutoff = CutoffMode::Epsilon;
  float cutoffEpsilon = 1e-5f;
  ShiftForm shiftForm = ShiftForm::Branch;
  bool invariantPosition = true;  // mark the position invariant + NoContraction on the shift
  bool fusedShift = false;        // x' = fma(eyeSign*separation, w - convergence, x): one rounding less
  bool compensatedShift = false;  // error-free transformations: x' within ~0.5 ULP of the exact shift
  bool haloFix = true;
  // The crash ladder's first rung (cli/process_failure.h): an earlier attempt of this conversion died
  // in the analyses' folded copy (SPIRV-Tools' optimizer), so the analyses run without it.
  bool foldedCopyCrashed = false;
  bool shiftThisStage = true;     // false for an intermediate stage of a pipeline
  // --corrections-only: the driver shifts every clip position itself (3D Vision Automatic, geo-11);
  // no stage gets the shift, only the per-eye corrections (deferred-unprojection's fixes).
  bool correctionsOnly = false;
  // Per-eye pixel maths (docs/stereo-math.md sections 2-4)
  bool perEyeView = true;             // per-eye camera position where a view vector offsets texture coordinates
  bool perEyeSpecular = false;        // also where it only feeds lighting (specular looks fine mono)
  std::string cameraUniform;          // --camera-uniform: this uniform (or block member) is the camera position
  bool deferredUnprojection = true;   // stereo-correct `InvM * vec4(ndc, depth, 1)` in deferred passes
  // Fixes only the source text can carry (decompiled HLSL's cbuffer-row unprojections, placed by
  // line) are recorded for the HLSL splice (RunRecord::deferred.textFixes) instead of reported as
  // left alone: set with --eye-source 3dmigoto, whose output is the dump's own text.
  bool sourceTextFixes = false;
  bool hudAtDepth = false;            // place proven-2D shaders at the eye depth `hudDepth`
  std::vector<std::string> onlyPasses;  // --pass: run only these (by name()); empty: all
  bool validateEach = false;
  bool printAll = false;          // dump SPIR-V after every pass to the report log
};

}  // namespace stereoshift
