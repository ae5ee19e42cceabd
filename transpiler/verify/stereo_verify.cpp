// This turns a shader (or the pre-rasterization stages of a pipeline) into a run on the device:
// the original and the transpiled SPIR-V, with inputs generated from the module's own reflection —
// every buffer, image, sampler and texel-buffer descriptor it declares, every vertex input, push
// constants (as a uniform buffer when over the device limit), pass-through stages in front of a lone
// tese or geometry shader — captured through transform feedback and compared per eye with the
// exact shift computed in double. Where a shader cannot run, the result's `error` says why in one line.
//
// The parts: verify_stages.cpp compiles the sources (buildStageModules), verify_inputs.cpp
// generates the data, harness_rewrites.cpp prepares the harness's copies of the modules; this file
// runs them (StereoCheck: the phases of verifyStereo, in order) and renders the result.
#include "transpiler/verify/stereo_verify.h"

#include "transpiler/verify/capture_instrument.h"
#include "transpiler/verify/harness_rewrites.h"
#include "transpiler/verify/stage_synthesis.h"
#include "transpiler/verify/verify_inputs.h"
#include "passes/ir/module.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>

namespace stereoshift::harness {

using spirv::Module;

nlohmann::json VerifyResult::json() const {
  nlohmann::json j = {{"ok", ok},
          {"error", error},
          {"mode", mode == EyeSelect::ViewIndex ? "multiview" : mode == EyeSelect::InstanceIndex ? "instanced" : "two-pass"},
          {"vertices", vertices},
          {"max_stereo_error_ulps", maxStereoUlps},
          {"bound_basis", boundBasis},
          {"cutoff_vertices", cutoffVertices},
          {"other_outputs_unchanged", otherOutputsUnchanged},
          {"halo_components_changed", haloComponentsChanged},
          {"max_moved_lane_error_ulps", maxMovedLaneUlps},
          {"moved_lane_components", movedLaneComponents},
          {"new_nans", newNaNs},
          {"disagreeing_components", disagreeingComponents},
          {"synthesized_stages", synthesizedStages},
          {"push_constants_as_buffer", pushConstantsAsBuffer},
          {"problems", problems}};
  if (mode == EyeSelect::Parameter) {
    j["mono_identical"] = monoIdentical;
    j["checked"] = {"eyeSign 0: every output bit for bit the original's",
                    "eyeSign -1 and +1: x against x + e*S*(w - C), every other output unchanged"};
    return j;
  }
  // The eye comes from the view or the instance: there is no eyeSign = 0 run to compare.
  j["mono_run"] = false;
  j["eye_sign_declared"] = eyeSignDeclared;
  j["eye_sign_ignored"] = eyeSignIgnored;
  if (mode == EyeSelect::ViewIndex)
    j["checked"] = {"view 0 and view 1: x against x + e*S*(w - C) for the view's eye, every other output unchanged",
                    "no eyeSign 0 run: a junk eyeSign parameter changes no output"};
  if (mode == EyeSelect::InstanceIndex) {
    j["checked"] = {"instance 2k+e against the original's instance k: x against x + e*S*(w - C) for eye e, every "
                    "other output unchanged",
                    "the layer / viewport index and the eye varying equal e",
                    "no eyeSign 0 run: a junk eyeSign parameter changes no output"};
    j["instances"] = instances;
    j["stereo_instances"] = 2 * instances;
    j["eye_routed"] = eyeRouted;
    j["eye_varying_written"] = eyeVaryingWritten;
  }
  return j;
}

namespace {

double ulpOf(double magnitude) {
  float m = static_cast<float>(std::max(magnitude, double(FLT_MIN)));
  return double(std::nextafter(m, INFINITY)) - double(m);
}

// The eye sign a single-pass stereo run gives the transpiled shader's eyeSign parameter, which it
// must no longer read: far from -1, 0, +1, so a shader that still read it would shift by several
// separations.
constexpr float kJunkEyeSign = 7.5f;

// One verifyStereo call, phase by phase: each phase returns false when the shader cannot run
// (result_.error says why) and the check stops there.
class StereoCheck {
 public:
  StereoCheck(VulkanContext& context, const std::vector<StageModules>& stages, const VerifySettings& settings)
      : context_(context), stages_(stages), settings_(settings), mode_(settings.eyeSource) {}

  VerifyResult run() {
    if (stages_.empty()) {
      result_.error = "no stages";
      return result_;
    }
    if (!parseModules() || !addLeadingStages() || !checkPipeline() || !relocatePushConstants()) return result_;
    result_.mode = mode_;
    if (!instrumentCaptures() || !bindViews() || !buildInputs()) return result_;
    dumpModules();
    shapeDraws();
    if (!captureOriginal()) return result_;
    const bool ran = mode_ == EyeSelect::Parameter ? checkTwoPass()
                     : mode_ == EyeSelect::ViewIndex ? checkMultiview()
                                                     : checkInstanced();
    if (!ran) return result_;
    judge();
    return result_;
  }

 private:
  bool stop(std::string error) {
    result_.error = std::move(error);
    return false;
  }

  // Both SPIR-V modules of every stage, made runnable on the harness alike.
  bool parseModules() {
    for (const auto& s : stages_) {
      std::string error;
      auto a = Module::parse(s.original, &error);
      auto b = Module::parse(s.transpiled, &error);
      if (!a || !b) return stop("unparsable SPIR-V: " + error);
      if (s.bindings == BindingClasses::D3dRegisters) {
        separateRegisterClasses(*a);
        separateRegisterClasses(*b);
      }
      // OpenGL shaders run through the same Vulkan-compatible rewrite, original and transpiled alike.
      const uint32_t blockBinding = 16 + static_cast<uint32_t>(originals_.size());
      if (!convertOpenGLForVulkan(*a, blockBinding, &error) && !error.empty()) return stop(error);
      convertOpenGLForVulkan(*b, blockBinding, &error);
      if (s.bindings == BindingClasses::OpenGL) {  // after the default block joined the uniform blocks
        separateOpenGLBindingClasses(*a);
        separateOpenGLBindingClasses(*b);
      }
      matchInvariance(*a, *b);
      feedDoubleInputsAsFloats(*a);
      feedDoubleInputsAsFloats(*b);
      if (&s == &stages_.back() && !s.agreeing.empty()) {
        const Module& transpiledInvariance = *b;
        auto c = Module::parse(s.agreeing, &error);
        if (!c) return stop("unparsable SPIR-V (the agreeing conversion): " + error);
        if (s.bindings == BindingClasses::D3dRegisters) separateRegisterClasses(*c);
        convertOpenGLForVulkan(*c, blockBinding, &error);
        if (s.bindings == BindingClasses::OpenGL) separateOpenGLBindingClasses(*c);
        // Compiled alike: the transpiled stage's invariance, not its own (a splice adds none where
        // the SPIR-V route marks the position; llvmpipe then contracts differently).
        std::erase_if(c->annotations, [](const spirv::Instruction& i) {
          return (i.opcode == spv::OpDecorate && i.operand(1) == uint32_t(spv::DecorationInvariant)) ||
                 (i.opcode == spv::OpMemberDecorate && i.operand(2) == uint32_t(spv::DecorationInvariant));
        });
        c->invalidateDefinitions();
        matchInvariance(*c, transpiledInvariance);
        feedDoubleInputsAsFloats(*c);
        agreeing_ = std::move(*c);
      }
      originals_.push_back(std::move(*a));
      transpiled_.push_back(std::move(*b));
    }
    return true;
  }

  // A tessellation-evaluation or geometry shader given alone runs behind synthesized pass-through
  // stages, the same in front of the original and the transpiled one.
  bool addLeadingStages() {
    Result<LeadingStages> synthesized = synthesizeLeadingStages(originals_.front());
    if (!synthesized) return stop(synthesized.error().message);
    std::vector<Module>& leading = synthesized->modules;
    const std::vector<std::string>& leadingNames = synthesized->names;
    originals_.insert(originals_.begin(), leading.begin(), leading.end());
    if (mode_ == EyeSelect::InstanceIndex)
      for (size_t i = 0; i < leading.size(); ++i)
        if (!handEyeOn(leadingNames[i], &leading[i])) return false;
    transpiled_.insert(transpiled_.begin(), leading.begin(), leading.end());
    result_.synthesizedStages = leadingNames;
    return true;
  }

  // Instanced: in front of the transpiled stage the synthesized stages hand the eye on, as
  // stereoshift converts them in a pipeline (the vertex stage takes it from the instance).
  bool handEyeOn(const std::string& name, Module* stage) {
    TranspileOptions o;
    o.target = TargetLanguage::Spirv;
    o.shiftThisStage = false;
    o.eye.select = EyeSelect::InstanceIndex;
    o.eye.eyeVaryingName = settings_.eyeVaryingName;
    o.eye.eyeVaryingLocation = settings_.eyeVaryingLocation;
    std::vector<uint32_t> words = stage->encode();
    TranspileResult converted =
        transpile(SourceFile{name, std::string(reinterpret_cast<const char*>(words.data()), words.size() * 4)}, o);
    std::string error;
    std::optional<Module> m;
    if (converted.ok && converted.output.size() % 4 == 0) {
      std::vector<uint32_t> out(converted.output.size() / 4);
      std::memcpy(out.data(), converted.output.data(), converted.output.size());
      m = Module::parse(out, &error);
    }
    if (!m)
      return stop("the synthesized " + name + " could not hand the eye on: " +
                  (converted.ok ? error : converted.diagnostics.format()));
    *stage = std::move(*m);
    return true;
  }

  // Consecutive stages must fit together, and the device must have what the stages need.
  bool checkPipeline() {
    for (size_t i = 0; i + 1 < originals_.size(); ++i)
      if (Status fits = checkStageInterface(originals_[i], originals_[i + 1]); !fits) return stop(fits.error().message);
    for (const auto& m : transpiled_) {
      std::string missing = missingFeature(m, context_.features());
      if (!missing.empty()) return stop(missing);
    }
    return true;
  }

  // Push constants over the device limit: a uniform buffer one set beyond every set in use.
  bool relocatePushConstants() {
    const uint32_t pushLimit = context_.properties().limits.maxPushConstantsSize;
    uint32_t pushBytes = 0, freeSet = 0;
    for (const auto* list : {&originals_, &transpiled_})
      for (const auto& m : *list) {
        pushBytes = std::max(pushBytes, pushConstantBytes(m));
        for (const auto& inst : m.annotations)
          if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationDescriptorSet))
            freeSet = std::max(freeSet, inst.operand(2) + 1);
      }
    if (pushBytes > pushLimit) {
      if (freeSet >= context_.properties().limits.maxBoundDescriptorSets)
        return stop("the push constants (" + std::to_string(pushBytes) + " bytes) exceed the device's " +
                    std::to_string(pushLimit) + "-byte limit and no descriptor set is free to hold them instead");
      for (auto* list : {&originals_, &transpiled_})
        for (auto& m : *list) pushConstantsToUniformBuffer(m, freeSet);
      result_.pushConstantsAsBuffer = true;
    }
    return true;
  }

  // Transform-feedback capture of the last stage of both, and where each captured component of the
  // original is in the transpiled capture (instanced mode adds the eye outputs, which the original
  // does not have).
  bool instrumentCaptures() {
    // Instanced: the harness's output carrying what the shader writes to the layer / viewport.
    if (mode_ == EyeSelect::InstanceIndex) routeName_ = exposeEyeRoute(transpiled_.back(), settings_.eyeRoute);
    Result<CaptureLayout> original = instrumentForCapture(originals_.back());
    if (!original) return stop(original.error().message);
    Result<CaptureLayout> transpiled = instrumentForCapture(transpiled_.back());
    if (!transpiled) return stop(transpiled.error().message);
    layoutA_ = std::move(*original);
    layoutB_ = std::move(*transpiled);
    inStereo_.assign(layoutA_.stride / 4, UINT32_MAX);
    std::vector<bool> matched(layoutA_.fields.size(), false);
    for (const auto& g : layoutB_.fields) {
      const CapturedField* match = nullptr;
      for (size_t i = 0; i < layoutA_.fields.size() && !match; ++i) {
        const auto& f = layoutA_.fields[i];
        if (!matched[i] && f.isPosition == g.isPosition && f.location == g.location && f.components == g.components) {
          matched[i] = true;
          match = &f;
        }
      }
      if (match) {
        for (uint32_t k = 0; k < g.components; ++k) inStereo_[match->offset / 4 + k] = g.offset / 4 + k;
      } else if (mode_ == EyeSelect::InstanceIndex && g.name == settings_.eyeVaryingName && g.components == 1) {
        eyeVaryingComponent_ = int(g.offset / 4);
      } else if (mode_ == EyeSelect::InstanceIndex && !routeName_.empty() && g.name == routeName_ && g.components == 1) {
        routeComponent_ = int(g.offset / 4);
      } else {
        return stop("original and transpiled shaders have different outputs");
      }
    }
    if (std::find(inStereo_.begin(), inStereo_.end(), UINT32_MAX) != inStereo_.end())
      return stop("original and transpiled shaders have different outputs");
    return !agreeing_ || instrumentAgreeing();
  }

  // The agreeing conversion's capture, and where each transpiled component is in it.
  bool instrumentAgreeing() {
    Result<CaptureLayout> layout = instrumentForCapture(*agreeing_);
    if (!layout) return stop(layout.error().message);
    layoutC_ = std::move(*layout);
    inAgreeing_.assign(layoutB_.stride / 4, UINT32_MAX);
    std::vector<bool> matched(layoutC_.fields.size(), false);
    for (const auto& g : layoutB_.fields)
      for (size_t i = 0; i < layoutC_.fields.size(); ++i) {
        const auto& f = layoutC_.fields[i];
        if (matched[i] || f.isPosition != g.isPosition || f.location != g.location || f.components != g.components)
          continue;
        matched[i] = true;
        for (uint32_t k = 0; k < g.components; ++k) inAgreeing_[g.offset / 4 + k] = f.offset / 4 + k;
        break;
      }
    if (std::find(matched.begin(), matched.end(), false) != matched.end() ||
        std::find(inAgreeing_.begin(), inAgreeing_.end(), UINT32_MAX) != inAgreeing_.end())
      return stop("the two conversions of the stage have different outputs");
    return true;
  }

  // Multiview: one copy of the transpiled stages per view, each reading its view's index.
  bool bindViews() {
    if (mode_ != EyeSelect::ViewIndex) return true;
    for (uint32_t view = 0; view < 2; ++view) {
      perView_.push_back(transpiled_);
      for (auto& m : perView_.back())
        if (Status bound = bindViewIndex(m, view); !bound) return stop(bound.error().message);
    }
    return true;
  }

  // Inputs, identical for both runs except for the eye parameters.
  bool buildInputs() {
    if (settings_.vertices) {
      base_.vertices = *settings_.vertices;
    } else {
      Result<VertexBuffer> vertices = buildVertices(originals_.front(), settings_.vertexCount);
      if (!vertices) return stop(vertices.error().message);
      base_.vertices = std::move(*vertices);
    }
    for (const auto& m : originals_)
      if (Status built = buildResources(m, &base_); !built) return stop(built.error().message);
    // The transpiled stages add the eye-parameter block: same inputs plus that one.
    stereoBase_ = base_;
    for (const auto& m : transpiled_)
      if (Status built = buildResources(m, &stereoBase_); !built) return stop(built.error().message);
    if (agreeing_) {
      agreeBase_ = base_;
      for (size_t i = 0; i + 1 < transpiled_.size(); ++i)
        if (Status built = buildResources(transpiled_[i], &agreeBase_); !built) return stop(built.error().message);
      if (Status built = buildResources(*agreeing_, &agreeBase_); !built) return stop(built.error().message);
    }
    return true;
  }

  // STEREOSHIFT_VERIFY_DUMP=<dir>: the modules as they run, for a look with spirv-dis.
  void dumpModules() const {
    const char* dump = std::getenv("STEREOSHIFT_VERIFY_DUMP");
    if (!dump) return;
    for (size_t i = 0; i < originals_.size(); ++i) {
      auto a = originals_[i].encode(), b = transpiled_[i].encode();
      std::ofstream(std::string(dump) + "/original" + std::to_string(i) + ".spv", std::ios::binary)
          .write(reinterpret_cast<const char*>(a.data()), std::streamsize(a.size() * 4));
      std::ofstream(std::string(dump) + "/transpiled" + std::to_string(i) + ".spv", std::ios::binary)
          .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size() * 4));
    }
  }

  // The topology the first stage takes, whole primitives of vertices, and the instances.
  void shapeDraws() {
    bool tessellation = false;
    const Module* geometry = nullptr;
    for (const auto& m : originals_) {
      tessellation |= m.executionModel() == spv::ExecutionModelTessellationControl;
      if (m.executionModel() == spv::ExecutionModelGeometry) geometry = &m;
    }
    count_ = settings_.vertexCount;
    if (tessellation) {
      base_.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
      base_.patchControlPoints = patchControlPoints(originals_);
      if (base_.patchControlPoints == 0) base_.patchControlPoints = 3;
      count_ -= count_ % base_.patchControlPoints;
    } else if (geometry) {
      count_ -= count_ % geometryInput(*geometry, &base_.topology);
    } else {
      base_.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
      count_ -= count_ % 3;
    }
    base_.vertexCount = count_;
    // Instanced: the original draws a few instances (so a shader whose outputs depend on the instance
    // shows whether the rewrite reads the right one), the stereo draw twice as many.
    instances_ = mode_ == EyeSelect::InstanceIndex ? std::max(1u, settings_.originalInstances) : 1;
    base_.instanceCount = instances_;
    result_.instances = instances_;
    stereoBase_.topology = base_.topology;
    stereoBase_.patchControlPoints = base_.patchControlPoints;
    stereoBase_.vertexCount = base_.vertexCount;
    stereoBase_.instanceCount = mode_ == EyeSelect::InstanceIndex ? 2 * instances_ : 1;
    agreeBase_.topology = base_.topology;
    agreeBase_.patchControlPoints = base_.patchControlPoints;
    agreeBase_.vertexCount = base_.vertexCount;
    agreeBase_.instanceCount = 1;
  }

  bool capture(std::vector<Module>& modules, const PipelineInputs& inputs, CaptureResult* out) {
    const bool original = &modules == &originals_;
    CaptureRequest request;
    request.pipeline = inputs;
    for (size_t i = 0; i < modules.size(); ++i)
      request.pipeline.stages.push_back({toVk(modules[i].executionModel()), modules[i].encode(), modules[i].entryPointName()});
    request.xfbStride = original ? layoutA_.stride : &modules == &agreeingStages_ ? layoutC_.stride : layoutB_.stride;
    // Room for tessellation / geometry amplification.
    request.expectedVertices = count_ * 64 * inputs.instanceCount;
    *out = context_.capture(request);
    return out->ok();
  }

  // The transpiled stages run with eyeSign = `eye` (the single-pass modes: a value they must ignore).
  bool captureStereo(std::vector<Module>& modules, float eye, CaptureResult* out) {
    PipelineInputs inputs = stereoBase_;
    // A shader without a shift (a 2D one in instanced mode) may have no parameters at all.
    if (Result<bool> set = applyEyeParameters(modules.back(), settings_, eye, &inputs); !set && settings_.shifted)
      return stop(set.error().message);
    if (!capture(modules, inputs, out)) return stop("transpiled: " + out->error);
    return true;
  }

  bool captureOriginal() {
    if (!capture(originals_, base_, &mono_)) return stop("original: " + mono_.error);
    result_.vertices = mono_.vertexCount();
    const CapturedField* position = layoutA_.position();
    px_ = position->offset / 4;
    pxStereo_ = inStereo_[px_];
    result_.otherOutputsUnchanged = true;
    // A captured component as the shader wrote it: a float, or an integer (instance ids, eyes).
    integerComponent_.assign(layoutA_.stride / 4, false);
    for (const auto& f : layoutA_.fields)
      for (uint32_t k = 0; k < f.components; ++k) integerComponent_[f.offset / 4 + k] = !f.isFloat;
    return true;
  }

  // Captured component `c` of the original as the shader names it: "'teClip'.y (component 5)".
  std::string componentName(uint32_t c) const {
    for (const auto& f : layoutA_.fields)
      if (c >= f.offset / 4 && c < f.offset / 4 + f.components)
        return "'" + f.name + "'" + (f.components > 1 ? std::string(".") + "xyzw"[c - f.offset / 4] : std::string()) +
               " (component " + std::to_string(c) + ")";
    return "component " + std::to_string(c);
  }

  std::string valueText(const CaptureResult& capture, uint32_t vertex, uint32_t component) const {
    const uint32_t original = &capture == &mono_ ? component
                              : uint32_t(std::find(inStereo_.begin(), inStereo_.end(), component) - inStereo_.begin());
    return original < integerComponent_.size() && integerComponent_[original]
               ? std::to_string(int32_t(capture.u32(vertex, component)))
               : std::to_string(capture.f32(vertex, component));
  }

  // Captured vertex `vm` of the original against vertex `vs` of a stereo run of eye sign `eye`: x
  // against the exact reference, every other component unchanged (halo outputs excepted).
  void compareVertex(const CaptureResult& stereo, uint32_t vm, uint32_t vs, float eye, const std::string& run) {
    double x = mono_.f32(vm, px_), w = mono_.f32(vm, px_ + 3);
    float got = stereo.f32(vs, pxStereo_);
    // The shader's guard, in its own fp32 terms (core/shift_spec.h).
    bool unshifted = !settings_.shifted || cutoffKeepsMono(settings_.cutoff, settings_.cutoffEpsilon, float(w));
    double shift = double(eye) * settings_.separation * (w - settings_.convergence);
    double reference = unshifted ? x : x + shift;
    if (unshifted && settings_.shifted && eye > 0) ++result_.cutoffVertices;
    double scale = std::max(std::fabs(x), std::fabs(double(settings_.separation) * (w - settings_.convergence)));
    if (std::isnan(got) && !std::isnan(x) && !std::isnan(w)) ++result_.newNaNs;
    double ulps;
    if (std::isnan(reference) || std::isinf(reference) || std::isinf(got))
      ulps = (std::isnan(reference) && std::isnan(got)) || double(got) == reference ? 0 : INFINITY;
    else
      ulps = std::fabs(got - reference) / ulpOf(scale);
    result_.maxStereoUlps = std::max(result_.maxStereoUlps, ulps);
    compareOtherComponents(stereo, vm, vs, run, reference - x, scale);
  }

  // Component `c` when it is a lane the halo pass moved (StageModules::movedLanes): checked against
  // mono + a * shift (`shift` the reference's, `scale` its ULP basis). False for any other component.
  bool compareMovedLane(const CaptureResult& stereo, uint32_t vm, uint32_t vs, uint32_t c, double shift, double scale) {
    for (const auto& f : layoutA_.fields) {
      if (f.isPosition || c < f.offset / 4 || c >= f.offset / 4 + f.components) continue;
      for (const auto& moved : stages_.back().movedLanes) {
        if (moved.output != f.name || c != f.offset / 4 + moved.lane) continue;
        const double mono = mono_.f32(vm, c), got = stereo.f32(vs, inStereo_[c]);
        const double reference = mono + double(moved.coefficient) * shift;
        const double basis = std::max(std::fabs(mono), std::fabs(double(moved.coefficient)) * scale);
        const double ulps = got == reference ? 0 : std::fabs(got - reference) / ulpOf(basis);
        result_.maxMovedLaneUlps = std::max(result_.maxMovedLaneUlps, std::isnan(ulps) ? INFINITY : ulps);
        ++result_.movedLaneComponents;
        if (mono_.u32(vm, c) != stereo.u32(vs, inStereo_[c])) ++result_.haloComponentsChanged;
        return true;
      }
    }
    return false;
  }

  // y, z, w and every other captured component: unchanged, except halo copies of the position.
  void compareOtherComponents(const CaptureResult& stereo, uint32_t vm, uint32_t vs, const std::string& run,
                              double shift, double scale) {
    for (uint32_t c = 0; c < layoutA_.stride / 4; ++c) {
      if (c == px_ || compareMovedLane(stereo, vm, vs, c, shift, scale)) continue;
      const uint32_t cs = inStereo_[c];
      // A copy of the position holds all of it: an output whose x merely equals the position's x at
      // this vertex (an integer-valued output, a constant 0 beside x = 0) is no copy (found with
      // generated game dumps, fuzz_decompiled_dump's generator).
      auto copiesPositionHere = [&](uint32_t first) {
        for (uint32_t k = 0; k < 4; ++k)
          if (mono_.u32(vm, first + k) != mono_.u32(vm, px_ + k)) return false;
        return true;
      };
      bool staleCopy = false;
      for (const auto& f : layoutA_.fields)
        staleCopy |= !f.isPosition && f.components == 4 && c == f.offset / 4 && copiesPositionHere(c) &&
                     stereo.u32(vs, cs) != stereo.u32(vs, pxStereo_);
      if (staleCopy) {  // a copy of the position left mono: the 3Dmigoto "halo"
        result_.otherOutputsUnchanged = false;
        if (result_.problems.size() < 8)
          result_.problems.push_back("vertex " + std::to_string(vs) + ": " + componentName(c) +
                                     ", a copy of the position, was not shifted with it (halo) in " + run);
        continue;
      }
      if (mono_.u32(vm, c) == stereo.u32(vs, cs)) continue;
      bool haloCopy = false, haloDerived = false;
      for (const auto& f : layoutA_.fields) {
        if (f.isPosition || c < f.offset / 4 || c >= f.offset / 4 + f.components) continue;
        // A copied position must carry exactly the shifted x of gl_Position; other outputs the
        // halo pass re-derived may move (their formula is the shader's own).
        if (f.components == 4 && c == f.offset / 4 && mono_.u32(vm, c) == mono_.u32(vm, px_)) {
          haloCopy = stereo.u32(vs, cs) == stereo.u32(vs, pxStereo_);
        } else {
          const auto& halo = stages_.back().haloOutputs;
          haloDerived = std::find(halo.begin(), halo.end(), f.name) != halo.end();
        }
      }
      if (haloCopy || haloDerived) {
        ++result_.haloComponentsChanged;
      } else {
        result_.otherOutputsUnchanged = false;
        if (result_.problems.size() < 8)
          result_.problems.push_back("vertex " + std::to_string(vs) + ": output " + componentName(c) +
                                     " changed for " + run + " (" + valueText(mono_, vm, c) + " became " +
                                     valueText(stereo, vs, cs) + ")");
      }
    }
  }

  // The eye sign of view / instance eye `e` (0 or 1): the left eye first unless the eyes are swapped.
  float signOf(uint32_t e) const { return (e == 0 ? -1.0f : 1.0f) * (settings_.swapEyes ? -1.0f : 1.0f); }

  // Single-pass: eyeSign is no longer an input. A junk value there must leave every captured bit
  // as it was.
  bool checkIgnoresEyeSign(std::vector<Module>& modules, const CaptureResult& withZero, const std::string& run) {
    {
      PipelineInputs scratch = stereoBase_;
      if (Result<bool> set = applyEyeParameters(modules.back(), settings_, kJunkEyeSign, &scratch); set && *set)
        result_.eyeSignDeclared = true;
    }
    if (!result_.eyeSignDeclared) {
      result_.eyeSignIgnored = true;  // nothing to set: the shader cannot read it
      return true;
    }
    CaptureResult junk;
    if (!captureStereo(modules, kJunkEyeSign, &junk)) return false;
    const bool same = junk.bytes == withZero.bytes;
    result_.eyeSignIgnored = result_.eyeSignIgnored && same;
    if (!same)
      result_.problems.push_back(run + ": eyeSign = " + std::to_string(kJunkEyeSign) +
                                 " changed the outputs: the shader still reads the eyeSign parameter");
    return true;
  }

  // Two-pass: eyeSign 0 bit for bit the original's; -1 and +1 against the reference.
  bool checkTwoPass() {
    result_.monoIdentical = true;
    for (float eye : {0.0f, -1.0f, 1.0f}) {
      CaptureResult stereo;
      if (!captureStereo(transpiled_, eye, &stereo)) return false;
      if (stereo.bytes.size() != mono_.bytes.size()) {
        result_.problems.push_back("eye " + std::to_string(int(eye)) + ": captured a different number of vertices");
        continue;
      }
      if (eye == 0.0f) {
        checkMonoIdentical(stereo);
        continue;
      }
      for (uint32_t v = 0; v < result_.vertices; ++v) compareVertex(stereo, v, v, eye, "eye " + std::to_string(int(eye)));
      if (agreeing_ && !compareAgreeing(stereo, eye)) return false;
    }
    return true;
  }

  // The agreeing conversion run with the same eye: every captured component bit for bit the same.
  bool compareAgreeing(const CaptureResult& stereo, float eye) {
    agreeingStages_ = transpiled_;
    agreeingStages_.back() = *agreeing_;
    PipelineInputs inputs = agreeBase_;
    if (Result<bool> set = applyEyeParameters(agreeingStages_.back(), settings_, eye, &inputs); !set)
      return stop(set.error().message);
    CaptureResult other;
    if (!capture(agreeingStages_, inputs, &other)) return stop("agreeing conversion: " + other.error);
    if (other.vertexCount() != stereo.vertexCount()) {
      result_.problems.push_back("eye " + std::to_string(int(eye)) + ": the two conversions captured different vertex counts");
      return true;
    }
    for (uint32_t v = 0; v < stereo.vertexCount(); ++v)
      for (uint32_t c = 0; c < layoutB_.stride / 4; ++c) {
        ++result_.agreementComponentsCompared;
        if (stereo.u32(v, c) == other.u32(v, inAgreeing_[c])) continue;
        if (result_.disagreeingComponents++ == 0)
          result_.problems.push_back("eye " + std::to_string(int(eye)) + ", vertex " + std::to_string(v) +
                                     ": component " + std::to_string(c) + " is " + std::to_string(stereo.f32(v, c)) +
                                     " here and " + std::to_string(other.f32(v, inAgreeing_[c])) +
                                     " in the agreeing conversion");
      }
    return true;
  }

  void checkMonoIdentical(const CaptureResult& stereo) {
    result_.monoIdentical = stereo.bytes == mono_.bytes;
    if (result_.monoIdentical) return;
    std::string where;
    for (uint32_t v = 0; v < result_.vertices && where.empty(); ++v)
      for (uint32_t c = 0; c < layoutA_.stride / 4 && where.empty(); ++c)
        if (mono_.u32(v, c) != stereo.u32(v, c))
          where = ": first at vertex " + std::to_string(v) + ", " + componentName(c) + " (" +
                  std::to_string(mono_.f32(v, c)) + " became " + std::to_string(stereo.f32(v, c)) + ")";
    result_.problems.push_back("eyeSign = 0 output differs from the original" + where);
  }

  // Multiview: view 0 and view 1 against the reference for their eyes; eyeSign ignored.
  bool checkMultiview() {
    result_.eyeSignIgnored = true;
    for (uint32_t view = 0; view < 2; ++view) {
      const std::string name = "view " + std::to_string(view);
      CaptureResult stereo;
      if (!captureStereo(perView_[view], 0.0f, &stereo)) return false;
      if (stereo.vertexCount() != mono_.vertexCount()) {
        result_.problems.push_back(name + ": captured a different number of vertices");
        continue;
      }
      for (uint32_t v = 0; v < result_.vertices; ++v) compareVertex(stereo, v, v, signOf(view), name);
      if (!checkIgnoresEyeSign(perView_[view], stereo, name)) return false;
    }
    return true;
  }

  // Instanced: instance 2k+e against the original's instance k for eye e, the eye routed and
  // written to the eye varying; eyeSign ignored.
  bool checkInstanced() {
    result_.eyeSignIgnored = true;
    CaptureResult stereo;
    if (!captureStereo(transpiled_, 0.0f, &stereo)) return false;
    const uint32_t perInstance = result_.vertices / instances_;
    if (stereo.vertexCount() != 2 * result_.vertices || perInstance * instances_ != result_.vertices) {
      result_.problems.push_back(std::to_string(2 * instances_) + " instances captured " +
                                 std::to_string(stereo.vertexCount()) + " vertices, not twice the " +
                                 std::to_string(result_.vertices) + " of the original's " + std::to_string(instances_));
    } else {
      result_.eyeRouted = routeComponent_ >= 0;
      result_.eyeVaryingWritten = eyeVaryingComponent_ >= 0;
      if (routeComponent_ < 0)
        result_.problems.push_back(std::string("the vertex shader writes no ") +
                                   (settings_.eyeRoute == EyeRoute::Layer ? "gl_Layer" : "gl_ViewportIndex"));
      if (eyeVaryingComponent_ < 0)
        result_.problems.push_back("the vertex shader writes no '" + settings_.eyeVaryingName + "' output");
      for (uint32_t vs = 0; vs < stereo.vertexCount(); ++vs) checkInstancedVertex(stereo, vs, perInstance);
    }
    return checkIgnoresEyeSign(transpiled_, stereo, "instanced draw");
  }

  void checkInstancedVertex(const CaptureResult& stereo, uint32_t vs, uint32_t perInstance) {
    // Instance 2k+e of the stereo draw is the original's instance k seen by eye e.
    const uint32_t instance = vs / perInstance, k = instance >> 1, e = instance & 1;
    const uint32_t vm = k * perInstance + vs % perInstance;
    const std::string name = "instance " + std::to_string(instance) + " (eye " + std::to_string(e) + ")";
    compareVertex(stereo, vm, vs, signOf(e), name);
    auto checkEye = [&](int component, const std::string& what, bool* ok) {
      if (component < 0 || stereo.u32(vs, uint32_t(component)) == e) return;
      if (*ok && result_.problems.size() < 8)
        result_.problems.push_back("vertex " + std::to_string(vs) + ": " + what + " is " +
                                   std::to_string(int32_t(stereo.u32(vs, uint32_t(component)))) + ", not the eye " +
                                   std::to_string(e) + " of " + name);
      *ok = false;
    };
    checkEye(routeComponent_, routeName_, &result_.eyeRouted);
    checkEye(eyeVaryingComponent_, settings_.eyeVaryingName, &result_.eyeVaryingWritten);
  }

  // The bounds, and the verdict.
  // The bound follows from the precision of the injected shift: three fp32 roundings (2.5 ULP) or
  // the compensated form (1 ULP). The shift always runs on the fp32 x and w the shader wrote, so a
  // shader that computes its position in double (converted at the end) is held to the same bound:
  // its fp64 arithmetic happens before the shift, the same in both runs (the eyeSign 0 run checks
  // that bit for bit), and the reference is built from the fp32 x and w it produced.
  std::string boundBasis() const {
    std::string basis = settings_.maxUlps <= 1.0 ? "compensated fp32 shift" : "fp32 shift, three roundings";
    if (transpiled_.back().hasCapability(spv::CapabilityFloat64))
      basis += "; the shader computes in fp64 and writes an fp32 position, the shift is fp32";
    return basis;
  }

  void judge() {
    result_.boundBasis = boundBasis();
    if (result_.maxStereoUlps > settings_.maxUlps)
      result_.problems.push_back("stereo error " + std::to_string(result_.maxStereoUlps) + " ULP exceeds the bound of " +
                                 std::to_string(settings_.maxUlps));
    if (result_.newNaNs) result_.problems.push_back(std::to_string(result_.newNaNs) + " new NaN x values");
    if (result_.maxMovedLaneUlps > kMovedLaneUlps)
      result_.problems.push_back("a moved lane's error " + std::to_string(result_.maxMovedLaneUlps) +
                                 " ULP exceeds the bound of " + std::to_string(kMovedLaneUlps));
    const bool eyeChecks = mode_ == EyeSelect::Parameter    ? result_.monoIdentical
                           : mode_ == EyeSelect::ViewIndex ? result_.eyeSignIgnored
                                                           : result_.eyeSignIgnored && result_.eyeRouted &&
                                                                 result_.eyeVaryingWritten;
    result_.ok = eyeChecks && result_.otherOutputsUnchanged && result_.maxStereoUlps <= settings_.maxUlps &&
                 result_.newNaNs == 0 && result_.problems.empty();
  }

  VulkanContext& context_;
  const std::vector<StageModules>& stages_;
  const VerifySettings& settings_;
  const EyeSelect mode_;
  VerifyResult result_;
  std::vector<Module> originals_, transpiled_;
  std::vector<std::vector<Module>> perView_;  // multiview: the transpiled stages of each view
  CaptureLayout layoutA_, layoutB_;            // the original's and the transpiled capture
  std::optional<Module> agreeing_;              // StageModules::agreeing of the last stage, prepared
  std::vector<Module> agreeingStages_;          // the transpiled stages with it last
  CaptureLayout layoutC_;                      // its capture
  std::vector<uint32_t> inAgreeing_;           // per transpiled component: its place in that capture
  PipelineInputs agreeBase_;
  std::vector<uint32_t> inStereo_;             // per original component: its place in the transpiled capture
  std::string routeName_;
  int eyeVaryingComponent_ = -1, routeComponent_ = -1;
  PipelineInputs base_, stereoBase_;
  uint32_t count_ = 0, instances_ = 1;
  CaptureResult mono_;
  uint32_t px_ = 0, pxStereo_ = 0;  // the position's x in the original's and the stereo capture
  std::vector<bool> integerComponent_;
};

}  // namespace

VerifyResult verifyStereo(VulkanContext& context, const std::vector<StageModules>& stages,
                          const VerifySettings& settings) {
  return StereoCheck(context, stages, settings).run();
}

}  // namespace stereoshift::harness
