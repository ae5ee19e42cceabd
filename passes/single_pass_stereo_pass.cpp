// single-pass-stereo: turns a mono shader into one that draws both eyes in one pass
// (--eye-source multiview | instanced). The shift itself stays stereo-shift's; what changes is where
// eyeSign comes from, which passes/eye_select.h says (the view index, or the instance's low bit and
// the `stereoEye` varyings that hand it on).
// The pass itself checks that the output language can express the mode (refusing with the reason
// and what to do instead), declares the view index of a multiview shader that gets the shift, and
// in instanced mode rewrites the vertex shader: every use of the instance index reads the original
// instance (`instance >> 1`), and the eye goes to the `stereoEye` varying and, from the stage that
// rasterizes (vertex, tessellation evaluation or geometry), to the render-target layer or the
// viewport index; the stages between hand it on.
#include "passes/eye_select.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"

#include "passes/ir/builder.h"
#include "passes/ir/replace_uses.h"

namespace stereoshift {

using spirv::Instruction;

namespace {

// Whether this pre-rasterization stage is the one that rasterizes (the last of its pipeline), 2D
// ones included: instanced mode draws each twice per instance, so each routes its eye whether it
// gets the shift or not.
bool rasterizingStage(const PassContext& ctx) {
  spv::ExecutionModel model = ctx.module.executionModel();
  bool preRaster = model == spv::ExecutionModelVertex || model == spv::ExecutionModelTessellationEvaluation ||
                   model == spv::ExecutionModelGeometry;
  return preRaster && (ctx.classification == Classification::Perspective ||
                       ctx.classification == Classification::ConstantW1 || ctx.shiftPosition);
}

// Refuses what the output cannot express, with the reason and what to do instead.
bool checkTarget(PassContext& ctx) {
  const EyeSelect select = ctx.options.eye.select;
  const char* flag = modeFlag(select);
  TargetLanguage target = outputLanguage(ctx);
  spv::ExecutionModel model = ctx.module.executionModel();
  bool tessOrGeometry = model == spv::ExecutionModelTessellationControl ||
                        model == spv::ExecutionModelTessellationEvaluation || model == spv::ExecutionModelGeometry;
  bool instanced = select == EyeSelect::InstanceIndex;
  bool writesLayerFromVertexStage = instanced && rasterizingStage(ctx) && model != spv::ExecutionModelGeometry;
  auto refuse = [&](const std::string& why) {
    ctx.diags.error(ctx.file, std::string(flag) + ": " + why);
    return false;
  };
  if (!ctx.output.canCarry(EditKind::SinglePassEye)) {
    // Instanced mode hands the eye on through a tessellation-control stage (in two passes it is
    // copied unchanged, and multiview changes nothing there).
    if (model != spv::ExecutionModelTessellationControl)
      return refuse(ctx.output.limitedBecause + ", which carries the two-pass shift only; choose --target spirv or "
                    "--target glsl");
    if (instanced)
      return refuse("the eye is handed on through the hull shader, and " + ctx.output.limitedBecause +
                    "; choose --target spirv or --target glsl");
  }

  if (instanced && (model == spv::ExecutionModelMeshEXT || model == spv::ExecutionModelMeshNV))
    return refuse("a mesh shader has no instance index to take the eye from; use --eye-source multiview");
  if (glslOutput(target) && openGlOutput(ctx, target)) {
    bool es = target == TargetLanguage::Essl;
    int version = glslOutputVersion(ctx, target);
    if (version < (es ? 300 : 330))
      return refuse(std::string("needs ") + (es ? "ESSL 300" : "GLSL 330") + " or later (this output is " +
                    std::to_string(version) + (es ? " es" : "") + "); add --target-version " + (es ? "300" : "330") +
                    (es ? " to every stage of the program (ESSL links one version only)" : ""));
    if (select == EyeSelect::ViewIndex && tessOrGeometry)
      return refuse("OpenGL multiview (GL_OVR_multiview2) does not allow tessellation or geometry shaders in a "
                    "multiview draw; use --eye-source instanced, or a Vulkan target (--target spirv)");
    const char* stageName = model == spv::ExecutionModelVertex ? "vertex" : "tessellation evaluation";
    if (writesLayerFromVertexStage && es)
      return refuse(std::string("an ESSL ") + stageName + " shader cannot write gl_Layer or gl_ViewportIndex; use "
                    "--eye-source multiview (GL_OVR_multiview2) for OpenGL ES, or route the eye through a geometry stage");
    if (writesLayerFromVertexStage && version < 410)
      return refuse(std::string("a ") + stageName + " shader writes gl_Layer / gl_ViewportIndex through "
                    "GL_ARB_shader_viewport_layer_array, which needs GLSL 410 (this output is " + std::to_string(version) +
                    "); add --target-version 410, or use --eye-source multiview (GL_OVR_multiview2)");
    if (instanced && !es && model == spv::ExecutionModelGeometry && rasterizingStage(ctx) &&
        ctx.options.eye.route == EyeRoute::Viewport && version < 410)
      return refuse("a geometry shader writes gl_ViewportIndex from GLSL 410 (this output is " + std::to_string(version) +
                    "); add --target-version 410, or use --eye-route layer (gl_Layer, GLSL 150)");
  }
  // Vulkan ESSL neither: no ESSL extension declares gl_Layer / gl_ViewportIndex before the geometry
  // stage (glslang refuses them), while the SPIR-V capability does exist.
  if (writesLayerFromVertexStage && target == TargetLanguage::Essl && !openGlOutput(ctx, target))
    return refuse(std::string("a Vulkan ESSL ") +
                  (model == spv::ExecutionModelVertex ? "vertex" : "tessellation evaluation") +
                  " shader cannot write gl_Layer or gl_ViewportIndex (no ESSL extension declares them before the "
                  "geometry stage); use --target spirv (the SPIR-V writes Layer through ShaderViewportIndexLayerEXT), "
                  "or --eye-source multiview (GL_EXT_multiview)");
  if (select == EyeSelect::ViewIndex && target == TargetLanguage::Hlsl && ctx.output.version &&
      *ctx.output.version < 61)
    return refuse("SV_ViewID needs shader model 6.1 (this is --target-version " +
                  std::to_string(*ctx.output.version) + "); drop --target-version or give 61 or later");
  return true;
}

// Rewrites every read of the instance index to the original instance (`instance >> 1`).
int rewriteInstanceReads(PassContext& ctx, uint32_t instanceVariable) {
  auto& m = ctx.module;
  // Any other use of the variable's pointer (passed to a function, copied as a pointer) would read
  // the doubled index where the rewrite cannot see it: refused rather than converted half-way.
  for (const auto& fn : m.functions)
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions) {
        bool read = (inst.opcode == spv::OpLoad && inst.operand(0) == instanceVariable) ||
                    ((inst.opcode == spv::OpCopyMemory || inst.opcode == spv::OpCopyMemorySized) &&
                     inst.operand(1) == instanceVariable && inst.operand(0) != instanceVariable);
        if (read) continue;
        for (size_t k = 0; k < inst.operands.size(); ++k)
          if (inst.operands[k] == instanceVariable && spirv::isValueOperand(inst, k)) {
            ctx.diags.error(ctx.file, "--eye-source instanced: the instance index '" + m.name(instanceVariable) +
                                          "' is " + (inst.opcode == spv::OpFunctionCall ? std::string("passed to a function by pointer")
                                          : inst.opcode == spv::OpCopyObject
                                              ? std::string("copied as a pointer (OpCopyObject)")
                                              : "used as a pointer (opcode " + std::to_string(inst.opcode) + ")") +
                                          ", where its reads cannot be rewritten to the original instance; "
                                          "load it where it is used, or use --eye-source multiview");
            return -1;
          }
      }
  // A copy straight out of the variable (OpCopyMemory / OpCopyMemorySized) reads it too: made a load
  // and a store first, so the rewrite below sees every read as a load.
  uint32_t valueType = m.pointeeType(m.definition(instanceVariable)->typeId);
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks)
      for (size_t i = 0; i < block.instructions.size(); ++i) {
        Instruction& inst = block.instructions[i];
        if ((inst.opcode != spv::OpCopyMemory && inst.opcode != spv::OpCopyMemorySized) || inst.operand(1) != instanceVariable)
          continue;
        uint32_t target = inst.operand(0), value = m.takeId();
        inst = Instruction(spv::OpStore, 0, 0, std::vector<uint32_t>{target, value});
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i),
                                  Instruction(spv::OpLoad, valueType, value, std::vector<uint32_t>{instanceVariable}));
        ++i;
      }
  m.invalidateDefinitions();
  std::vector<uint32_t> loads;
  for (const auto& fn : m.functions)
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions)
        if (inst.opcode == spv::OpLoad && inst.operand(0) == instanceVariable) loads.push_back(inst.resultId);
  for (uint32_t load : loads) {
    uint32_t original = m.takeId();
    spirv::replaceAllUses(m, load, original);  // before the shift exists, so it keeps reading `load`
    for (auto& fn : m.functions)
      for (auto& block : fn.blocks)
        for (size_t i = 0; i < block.instructions.size(); ++i)
          if (block.instructions[i].resultId == load) {
            uint32_t type = block.instructions[i].typeId;
            const Instruction* typeDef = m.definition(type);
            bool isSigned = typeDef && typeDef->operand(1) == 1;
            block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1,
                                      Instruction(isSigned ? spv::OpShiftRightArithmetic : spv::OpShiftRightLogical,
                                                  type, original,
                                                  std::vector<uint32_t>{load, m.constantInt(1)}));
            m.invalidateDefinitions();  // the insertion may have moved the block's instructions
            i = block.instructions.size();
          }
  }
  m.invalidateDefinitions();
  return static_cast<int>(loads.size());
}

// Declares this stage's `stereoEye` output that hands the eye on (to the fragment stage, or to the
// next pre-rasterization stage); 0 (with an error) when its location is taken.
uint32_t declareEyeVaryingOutput(PassContext& ctx) {
  uint32_t varying = ensureEyeVarying(ctx, spv::StorageClassOutput);
  if (varying) {
    ctx.record.singlePass.eyeVaryingName = eyeVaryingName(ctx, spv::StorageClassOutput);
    ctx.record.singlePass.eyeVaryingLocation = ctx.options.eye.eyeVaryingLocation;
  }
  return varying;
}

// Inserts `code` at the start of the entry point (after its function variables).
void prependToEntry(spirv::Module& m, const std::vector<Instruction>& code) {
  spirv::Function* entry = m.function(m.entryFunctionId());
  auto& insts = entry->blocks.front().instructions;
  size_t at = 0;
  while (at < insts.size() && insts[at].opcode == spv::OpVariable) ++at;
  insts.insert(insts.begin() + static_cast<long>(at), code.begin(), code.end());
  m.invalidateDefinitions();
}

// Inserts the code `make` returns before every EmitVertex / EmitStreamVertex of a geometry shader
// (its outputs are undefined after each emit, so each vertex gets its own stores).
template <typename Make>
int insertBeforeEachEmit(spirv::Module& m, Make make) {
  int emits = 0;
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks)
      for (size_t i = 0; i < block.instructions.size(); ++i) {
        spv::Op op = block.instructions[i].opcode;
        if (op != spv::OpEmitVertex && op != spv::OpEmitStreamVertex) continue;
        std::vector<Instruction> code = make();
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i), code.begin(), code.end());
        i += code.size();
        ++emits;
      }
  m.invalidateDefinitions();
  return emits;
}

// The variable the eye is routed to: the layer (gl_Layer) or the viewport index.
uint32_t declareEyeRouteTarget(PassContext& ctx) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  bool layer = o.route == EyeRoute::Layer;
  bool geometry = m.executionModel() == spv::ExecutionModelGeometry;
  uint32_t target = addIntVariable(m, spv::StorageClassOutput, layer ? "gl_Layer" : "gl_ViewportIndex");
  if (layer && !geometry && outputLanguage(ctx) == TargetLanguage::Hlsl) {
    std::string who;
    if (locationTaken(m, spv::StorageClassOutput, o.eyeVaryingLocation + 1, &who)) {
      ctx.diags.error(ctx.file, "--eye-source instanced: output location " + std::to_string(o.eyeVaryingLocation + 1) +
                                    " of the layer output (SV_RenderTargetArrayIndex) is taken by '" + who +
                                    "'; choose free locations with --eye-varying-location (it takes that one and the next)");
      return 0;
    }
    // SPIRV-Cross writes SV_RenderTargetArrayIndex from geometry shaders only (D3D12 allows it from
    // any stage that feeds the rasterizer, VPAndRTArrayIndexFromAnyShaderFeedingRasterizer): a
    // plain output carrying the semantic, which the back end puts back like any source semantic.
    m.setName(target, "stereoLayer");  // SPIRV-Cross reserves gl_ names for its built-ins
    m.decorate(target, spv::DecorationLocation, {o.eyeVaryingLocation + 1});
    m.decorateString(target, spv::DecorationUserSemantic, "SV_RenderTargetArrayIndex");
    m.addExtension("SPV_GOOGLE_decorate_string");
    m.addExtension("SPV_GOOGLE_hlsl_functionality1");
    return target;
  }
  m.decorate(target, spv::DecorationBuiltIn, {uint32_t(layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex)});
  if (!layer) m.addCapability(spv::CapabilityMultiViewport);
  if (!geometry) {
    // Layer / ViewportIndex from the vertex or tessellation evaluation stage:
    // VK_EXT_shader_viewport_index_layer, GL_ARB_shader_viewport_layer_array, D3D's SV_ViewportArrayIndex.
    // A geometry shader writes both natively (capability Geometry).
    m.addCapability(spv::CapabilityShaderViewportIndexLayerEXT);
    m.addExtension("SPV_EXT_shader_viewport_index_layer");
  }
  return target;
}

// Instanced: the eye (the instance's low bit in the vertex stage, the handed-on varying after it)
// goes to the `stereoEye` output and, in the stage that rasterizes, to the layer or viewport index:
// at the start of the entry point, or before every emit of a geometry shader.
bool routeInstancedEye(PassContext& ctx) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  spv::ExecutionModel model = m.executionModel();
  bool rasterizes = rasterizingStage(ctx);
  bool layer = o.route == EyeRoute::Layer;
  if (rasterizes && builtInVariable(m, layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex)) {
    ctx.diags.error(ctx.file, std::string("--eye-source instanced: the shader writes ") +
                                  (layer ? "gl_Layer" : "gl_ViewportIndex") + " itself; the eye cannot be routed there "
                                  "(try --eye-route " + (layer ? "viewport" : "layer") + ")");
    return false;
  }
  uint32_t varying = declareEyeVaryingOutput(ctx);
  if (!varying) return false;
  uint32_t target = rasterizes ? declareEyeRouteTarget(ctx) : 0;
  if (rasterizes && !target) return false;
  bool failed = false;
  auto storeEye = [&]() {
    std::vector<Instruction> code;
    uint32_t eye = model == spv::ExecutionModelVertex ? emitInstanceEyeBit(ctx, code) : emitLoadHandedOnEye(ctx, code);
    if (!eye) {
      failed = true;
      return code;
    }
    spirv::Builder b(m, code);
    if (target) b.store(target, eye);
    b.store(varying, eye);
    return code;
  };
  if (model == spv::ExecutionModelGeometry) {
    ctx.record.singlePass.emitsRouted = insertBeforeEachEmit(m, storeEye);
  } else {
    prependToEntry(m, storeEye());
  }
  if (failed) return false;
  if (target) ctx.record.singlePass.eyeWrittenTo = layer ? "layer" : "viewport";
  else ctx.record.singlePass.eyeHandedOn = true;
  return true;
}

// OpenGL multiview: SPIRV-Cross writes gl_ViewID_OVR in vertex shaders only, so the vertex stage
// hands the view on to the fragment stage's per-eye fixes as `stereoEye`, as instanced mode does.
bool handOnViewIndex(PassContext& ctx) {
  auto& m = ctx.module;
  uint32_t varying = declareEyeVaryingOutput(ctx);
  if (!varying) return false;
  std::vector<Instruction> code;
  uint32_t viewIndex = ensureViewIndex(ctx);
  uint32_t view = emitLoad(m, code, viewIndex);
  const Instruction* type = m.definition(m.pointeeType(m.definition(viewIndex)->typeId));
  if (type && type->operand(1) == 0) {  // gl_ViewID_OVR is a uint
    spirv::Builder b(m, code);
    uint32_t asInt = b.reserveId();
    view = b.addAs(asInt, spv::OpBitcast, m.typeInt(32, true), {view});
  }
  spirv::Builder(m, code).store(varying, view);
  prependToEntry(m, code);
  // GL_OVR_multiview lets only gl_Position depend on the view; this output does (and the shifted
  // halo outputs may), which GL_OVR_multiview2, the extension SPIRV-Cross declares, allows.
  ctx.record.singlePass.requiredExtension = "GL_OVR_multiview2 (plain GL_OVR_multiview lets only gl_Position depend on the view)";
  return true;
}

class SinglePassStereoPass final : public Pass {
 public:
  const char* name() const override { return "single-pass-stereo"; }

  PassResult run(PassContext& ctx) override {
    const EyeSelect select = ctx.options.eye.select;
    if (select == EyeSelect::Parameter) return PassResult::Unchanged;
    ctx.record.singlePass.mode = select == EyeSelect::ViewIndex ? "multiview" : "instanced";
    if (ctx.classification == Classification::AlreadyStereo) return PassResult::Unchanged;
    if (!checkTarget(ctx)) return PassResult::Failed;
    auto& m = ctx.module;
    spv::ExecutionModel model = m.executionModel();
    if (select == EyeSelect::ViewIndex) {
      TargetLanguage target = outputLanguage(ctx);
      if (model == spv::ExecutionModelVertex && rasterizingStage(ctx) && glslOutput(target) && openGlOutput(ctx, target)) {
        if (!handOnViewIndex(ctx)) return PassResult::Failed;
        return PassResult::Changed;
      }
      // Declared here for a shader that gets the shift (fixes of other stages declare it on use).
      if (!ctx.shiftPosition) return PassResult::Unchanged;
      ensureViewIndex(ctx);
      return PassResult::Changed;
    }
    // Instanced: the vertex stage takes the eye from the instance; the stages after it hand it on
    // up to the one that rasterizes, which routes it (the fragment stage reads it on use).
    bool handsOn = ctx.classification == Classification::Intermediate || model == spv::ExecutionModelTessellationControl;
    if (!rasterizingStage(ctx) && !handsOn) return PassResult::Unchanged;
    if (model == spv::ExecutionModelVertex) {
      uint32_t instance = ensureInstanceIndex(ctx);
      int rewritten = rewriteInstanceReads(ctx, instance);
      if (rewritten < 0) return PassResult::Failed;
      ctx.record.singlePass.instanceReadsRewritten = rewritten;
    }
    if (!routeInstancedEye(ctx)) return PassResult::Failed;
    return PassResult::Changed;
  }
};

}  // namespace

std::unique_ptr<Pass> createSinglePassStereoPass() { return std::make_unique<SinglePassStereoPass>(); }

// Rewrites reads of the instance index and adds outputs other than the position: the position's
// pointers and values stay, the folded copy no longer matches the module.
PassInfo singlePassStereoPassInfo() {
  return {"single-pass-stereo", createSinglePassStereoPass,
          "draws both eyes in one pass: eyeSign from the view index (multiview) or the instance index (instanced; "
          "the original instance given to the shader, the eye handed on to the rasterizing stage and routed to the "
          "layer or viewport)",
          "--eye-source multiview | instanced",
          "after detection (it routes 2D vertex shaders too) and before eye-params and the shift, so the instance "
          "reads it rewrites are only the application's own",
          {"clip-position-detection"}, kNoAnalyses, kClipPositionAnalysis, editSet(EditKind::SinglePassEye),
          // Only in the single-pass modes: a two-pass conversion's report never shows it.
          [](const PassOptions& options) { return options.eye.select != EyeSelect::Parameter; }};
}

}  // namespace stereoshift
