// Accuracy by execution: runs the original and the transpiled pipeline on lavapipe with inputs
// generated from the shader's reflected interface, and compares every captured output against the
// exact stereo reference `x + e*S*(w - C)` computed in double from the original's outputs.
#pragma once

#include "transpiler/verify/vk_harness.h"
#include "transpiler/stereoshift.h"
#include "passes/ir/module.h"
#include "passes/run_record.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace stereoshift::harness {

// How a stage's bindings number its resources. Vulkan (and HLSL with [[vk::binding]]): one binding
// space for every kind. D3D registers: b, t, s and u are separate namespaces that glslang maps onto
// one Vulkan binding space (cbuffer b0 and Texture2D t0 both become binding 0). OpenGL GLSL / ESSL:
// texture units, uniform-block, storage-block, image and atomic-counter bindings are separate
// namespaces too (`layout(binding = 0)` on a sampler2D and on a uniform block is legal). The harness
// moves each class of the last two to its own range before binding.
enum class BindingClasses { Shared, D3dRegisters, OpenGL };

struct StageModules {
  VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
  std::vector<uint32_t> original;    // SPIR-V of the mono shader
  std::vector<uint32_t> transpiled;  // SPIR-V after stereoshift's passes
  std::string entry = "main";
  std::vector<std::string> haloOutputs;  // outputs the halo pass re-derived from the shifted position
  // Lanes the halo pass moved by `coefficient` times the shift of x: each held to the mono value
  // plus coefficient * (reference x - x), within kMovedLaneUlps.
  std::vector<HaloFacts::MovedLane> movedLanes;
  BindingClasses bindings = BindingClasses::Shared;
  // The last stage only, optional: another conversion of the same shader (the SPIR-V route's, beside
  // a spliced text) whose every captured output must equal the transpiled one's, bit for bit, in
  // each eye: what the text carries is what the IR says (halo outputs derived from the position,
  // whose own values the stereo reference cannot tell).
  std::vector<uint32_t> agreeing;
};

constexpr double kMovedLaneUlps = 4.5;

struct VerifySettings {
  float separation = 0.065f;
  float convergence = 3.0f;
  CutoffMode cutoff = CutoffMode::Epsilon;  // the cutoff the transpiled shader was built with
  float cutoffEpsilon = 1e-5f;              // (Epsilon with 0: exact)
  uint32_t vertexCount = 96;
  std::optional<VertexBuffer> vertices;  // explicit vertex data instead of generated (stress tests)
  std::string eyeSignName = "eyeSign", separationName = "separation", convergenceName = "convergence";
  // The bound on the stereo error, in ULPs of max(|x|, |S(w - C)|). The injected code rounds three
  // times in fp32: d = w - C (error <= |eS| ulp(d)/2 <= 1 ulp of the shift), p = eS*d (<= 1/2 ulp),
  // x + p (<= ulp(x')/2 <= 1 ulp, since |x'| <= 2 max): 2.5 ULP is the analytic bound of that code.
  // Reaching 1 ULP needs a fused or compensated evaluation (see the benchmark); not done yet.
  double maxUlps = 2.5;
  // Where the transpiled shader takes the eye from (the conversion's --eye-source): Parameter runs
  // it with eyeSign 0, -1, +1; ViewIndex once per view (view 0 the left eye); InstanceIndex drawn
  // with twice the original's instances (instance 2k+e: the original instance k, eye e).
  EyeSelect eyeSource = EyeSelect::Parameter;
  bool swapEyes = false;                // single-pass: view 0 / even instances are the right eye
  EyeRoute eyeRoute = EyeRoute::Layer;  // instanced: where the vertex stage writes the eye
  std::string eyeVaryingName = "stereoEye";
  uint32_t eyeVaryingLocation = 15;
  uint32_t originalInstances = 2;       // instanced: instances of the original's draw
  // False for a shader that gets no shift but is still rewritten (instanced mode routes the eye of
  // 2D vertex shaders too): x must then stay as it is in both eyes.
  bool shifted = true;
};

struct VerifyResult {
  bool ok = false;
  std::string error;            // why the shader could not run (one line), not an accuracy failure
  uint32_t vertices = 0;
  bool monoIdentical = false;   // eyeSign = 0: every output bit for bit equal to the original
  double maxStereoUlps = 0;     // largest |x' - x_ref| in ULPs of max(|x|, |S(w - C)|)
  // Which bound maxStereoUlps was held to and why (the precision the shift is computed in, and the
  // precision the shader computes its position in; docs/stereo-math.md, section 6).
  std::string boundBasis;
  uint32_t cutoffVertices = 0;  // vertices left unshifted by the cutoff
  bool otherOutputsUnchanged = false;  // y, z, w and non-derived varyings identical per eye
  uint32_t haloComponentsChanged = 0;  // components of halo outputs that moved with the shift
  // StageModules::movedLanes: the largest error of a moved lane against mono + a * (x_ref - x), in
  // ULPs of max(|the lane|, |a| * max(|x|, |S(w - C)|)). Its bound, kMovedLaneUlps = 4.5: the shifted
  // x carries 2.5 ULP of max(|x|, |S(w - C)|) (maxUlps), x' - x rounds once (0.5, its size at most
  // that), the product by a once (0.5 of |a| times it), the sum once (1 ULP of max(lane, |a| * it),
  // the sum being at most twice that).
  double maxMovedLaneUlps = 0;
  uint32_t movedLaneComponents = 0;  // moved-lane components compared
  uint32_t newNaNs = 0;         // x became NaN although the original x and w were not NaN
  // With StageModules::agreeing (two-pass only): components of the stereo runs that differ between
  // the two conversions, and how many were compared.
  uint32_t disagreeingComponents = 0, agreementComponentsCompared = 0;
  std::vector<std::string> synthesizedStages;  // pass-through stages run in front of the given ones
  bool pushConstantsAsBuffer = false;  // push constants over the device limit, bound as a uniform buffer
  std::vector<std::string> problems;
  // Single-pass modes: no eyeSign = 0 run (monoIdentical stays false); instead a junk eyeSign must
  // change no output (the shader no longer reads it). Instanced: the eye the vertex stage writes.
  EyeSelect mode = EyeSelect::Parameter;
  bool eyeSignDeclared = false;  // the transpiled shader still declares the eyeSign parameter
  bool eyeSignIgnored = false;   // ... and a junk value there changed no captured bit
  uint32_t instances = 1;        // instances of the original's draw (instanced: the stereo one has twice)
  bool eyeRouted = false;        // instanced: gl_Layer / gl_ViewportIndex equals the eye on every vertex
  bool eyeVaryingWritten = false;  // instanced: the stereoEye varying equals the eye on every vertex
  nlohmann::json json() const;
};

// D3D's register classes, each moved to its own range of Vulkan bindings (what glslang's
// --shift-{cbuffer,sampler,uav,texture}-binding do at compile time), for HLSL without
// [[vk::binding]]. Apply it to an original and its transpiled copy alike: the injected cbuffer
// (a b register) stays where the conversion put it.
void separateRegisterClasses(spirv::Module& module);

// OpenGL's binding namespaces, each moved to its own range of Vulkan bindings, for OpenGL GLSL /
// ESSL (not Vulkan GLSL): uniform blocks stay where they are (the harness's default uniform block
// and the injected eye block among them), texture units (samplers, textures) move by 256, images
// by 512, storage blocks by 768, atomic counters by 1024. Apply it to an original and its
// transpiled copy alike, after convertOpenGLForVulkan.
void separateOpenGLBindingClasses(spirv::Module& module);

// Compiles the pre-rasterization stages of `sources` (fragment / compute are dropped) both as the
// original SPIR-V and through stereoshift's passes (only the last stage shifted), in pipeline order.
// `classification` receives the last stage's classification. False with diagnostics on failure.
bool buildStageModules(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                       std::vector<StageModules>* stages, std::string* classification, Diagnostics& diags);

// The stages form one pipeline (vertex first); the last one is captured. settings.eyeSource must be
// the mode the stages were converted in.
VerifyResult verifyStereo(VulkanContext& context, const std::vector<StageModules>& stages,
                          const VerifySettings& settings);

}  // namespace stereoshift::harness
