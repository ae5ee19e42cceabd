// Depth-based stereo reprojection: turns a description of what the application has (the colour and
// depth of one rendered view, how its depth is encoded, where the eye parameters live) into the two
// shaders of a full-screen pass that synthesizes the other eye (or both eyes from the centre view):
// a full-screen-triangle vertex shader and the reprojection fragment shader, in any output language.
// The shaders are written as Vulkan GLSL here and then go through the same front end, validation and
// back end as every converted shader (transpile()), so each output is compiled and checked the same
// way. The maths is docs/stereo-math.md section 5.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "transpiler/transpile_options.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// What the depth texture holds.
enum class ReprojectDepth {
  Linear,       // the eye-space depth w itself (positive, world units), e.g. a linear-depth G-buffer
  ZeroToOne,    // device depth of a perspective projection with z_ndc in [0, 1] (Vulkan, D3D, Metal)
  MinusOneToOne // device depth of an OpenGL projection, z_ndc in [-1, 1], stored as (z_ndc + 1) / 2
};

// How the bracket around the first crossing found by the linear search is narrowed.
enum class ReprojectRefinement { None, Bisection, Secant };
// Where the colour of a hit comes from: the texel at the solved position, or the two samples of the
// final bracket mixed by where the solution lies between them (the seed article's rule).
enum class ReprojectColour { Nearest, Interpolated };
// What a disoccluded pixel (seen by the target eye, hidden in the source) shows: the background
// texel next to the occluder's edge, or the coarse search's farther sample as it is.
enum class DisocclusionFill { Background, FartherSample };
// Which view the colour and depth come from: one eye (the other is synthesized; also the source eye
// itself comes out unchanged), or the centre (mono) view, reprojected to each eye with half the parallax.
enum class ReprojectSource { LeftEye, RightEye, Centre };

struct ReprojectOptions {
  // The eye parameters exactly as the transpiler declares them (names, block, set / binding, spec
  // ids); eyeSign is the eye to synthesize. `Auto` means a uniform block, like a Vulkan shader's.
  EyeParamOptions eye;
  ReprojectSource source = ReprojectSource::LeftEye;
  // Depth: a perspective projection is given by near/far (far absent: infinite) or by its two depth
  // coefficients z_clip = depthScale * z_eye + depthOffset (P[2][2], P[2][3] of a GL-style matrix,
  // w_clip = -z_eye); reversedZ flips near/far.
  ReprojectDepth depth = ReprojectDepth::ZeroToOne;
  bool reversedZ = false;
  double nearPlane = 0.1;
  std::optional<double> farPlane;  // none: infinite far plane
  std::optional<double> depthScale, depthOffset;  // both or neither; they override near/far
  // The search: `samples` candidates for parallax factors t = 1 - C/w from -searchNear (in front of
  // the screen) to 1 (infinitely far), i.e. source positions P - k*t over [P - s, P + s*searchNear]
  // for a maximum parallax s = |k| (the seed article's [P - s/2, P + s] with its own range).
  int samples = 8;
  double searchNear = 0.5;
  ReprojectRefinement refinement = ReprojectRefinement::Bisection;
  int refinementSteps = 3;
  ReprojectColour colour = ReprojectColour::Nearest;
  DisocclusionFill fill = DisocclusionFill::Background;
  bool maskOutput = false;  // also write a disocclusion mask (1 = disoccluded) to location 1
  // Bindings of the source textures in the eye parameters' descriptor set.
  uint32_t colourBinding = 0, depthBinding = 1;
  // Output
  TargetLanguage target = TargetLanguage::Spirv;
  std::optional<int> targetVersion;
};

// The source's depth read as the inverse eye depth: 1/w = stored * scale + offset (perspective), or
// 1/stored (linear). Exact in double, rounded once to float in the shader.
struct DepthDecode {
  bool linear = false;
  double scale = 0, offset = 0;
};
DepthDecode depthDecode(const ReprojectOptions& options);

// Empty when the options make sense; otherwise one message per problem ("--samples must be ...").
std::vector<std::string> checkReprojectOptions(const ReprojectOptions& options);

// The Vulkan GLSL the outputs are made from (OpenGL GLSL with loose uniforms).
std::string reprojectVertexSource(const ReprojectOptions& options);
std::string reprojectFragmentSource(const ReprojectOptions& options);

struct ReprojectShader {
  Stage stage = Stage::Vertex;
  std::string fileName;  // reproject.vert, reproject.frag.hlsl, ... for options.target
  std::string output;    // text, or SPIR-V bytes
  bool binary = false;
};

struct ReprojectResult {
  bool ok = false;
  std::vector<ReprojectShader> shaders;  // vertex, fragment
  Diagnostics diagnostics;
  nlohmann::json report;  // the options, the depth decode, the eye declaration, each output's report
};

// Writes, compiles, validates and emits both shaders for options.target.
ReprojectResult generateReprojectShaders(const ReprojectOptions& options);

// Option names as the CLI and the report spell them.
const char* reprojectDepthName(ReprojectDepth d);
const char* reprojectRefinementName(ReprojectRefinement r);
const char* reprojectColourName(ReprojectColour c);
const char* disocclusionFillName(DisocclusionFill f);
const char* reprojectSourceName(ReprojectSource s);
// The options as the JSON report states them.
nlohmann::json describeReprojectOptions(const ReprojectOptions& options);

}  // namespace stereoshift
