// single-pass-stereo: turns a mono shader into one that draws both eyes in one pass
// (--eye-source multiview | instanced). The shift itself stays stereo-shift's; what changes is where
// eyeSign comes from, and this file is the one place that says so (emitDerivedEyeSign, which
// emitLoadEyeParam calls for eyeSign in these modes):
//   multiview: the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID), view 0 the left eye;
//   instanced: the low bit of the instance index in the vertex stage (the application doubles the
//     instance count), a flat varying `stereoEye` written by the vertex stage in the fragment stage
//     (also for OpenGL multiview, where SPIRV-Cross writes gl_ViewID_OVR in vertex shaders only).
// The pass itself checks that the output language can express the mode (refusing with the reason
// and what to do instead), declares the view index of a multiview shader that gets the shift, and
// in instanced mode rewrites the vertex shader: every use of the instance index reads the original
// instance (`instance >> 1`), and the eye goes to the render-target layer or the viewport index and
// to the `stereoEye` varying.
#include "passes/pass.h"

#include "passes/ir/replace_uses.h"

namespace stereoshift {

using spirv::Instruction;

namespace {

bool glslOutput(TargetLanguage t) { return t == TargetLanguage::Glsl || t == TargetLanguage::Essl; }

// The output language, as the back end will resolve it (Auto: the input's own).
TargetLanguage outputLanguage(const PassContext& ctx) {
  if (ctx.options.target != TargetLanguage::Auto) return ctx.options.target;
  switch (ctx.source.language) {
    case SourceLanguage::Hlsl: return TargetLanguage::Hlsl;
    case SourceLanguage::Spirv: return TargetLanguage::Spirv;
    case SourceLanguage::Glsl: return ctx.source.es ? TargetLanguage::Essl : TargetLanguage::Glsl;
  }
  return TargetLanguage::Glsl;
}

// Whether a GLSL/ESSL output has OpenGL (not Vulkan) semantics, as the back end decides it.
bool openGlOutput(const PassContext& ctx, TargetLanguage target) {
  if (!glslOutput(target)) return false;
  bool es = target == TargetLanguage::Essl;
  bool openGlVersion = ctx.options.targetVersion && *ctx.options.targetVersion < (es ? 310 : 400);
  bool sameDialect = ctx.source.language == SourceLanguage::Glsl && es == ctx.source.es;
  bool vulkan = ctx.source.vulkan && (sameDialect || ctx.source.language != SourceLanguage::Glsl) && !openGlVersion;
  return !vulkan;
}

// The GLSL/ESSL version the output will have.
int glslOutputVersion(const PassContext& ctx, TargetLanguage target) {
  bool es = target == TargetLanguage::Essl;
  bool sameDialect = ctx.source.language == SourceLanguage::Glsl && es == ctx.source.es;
  return ctx.options.targetVersion.value_or(sameDialect ? ctx.source.version : (es ? 310 : 450));
}

const char* modeFlag(EyeSelect select) {
  return select == EyeSelect::ViewIndex ? "--eye-source multiview" : "--eye-source instanced";
}

uint32_t builtInVariable(const spirv::Module& m, spv::BuiltIn builtIn) {
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && m.decorationValue(inst.resultId, spv::DecorationBuiltIn) == uint32_t(builtIn))
      return inst.resultId;
  return 0;
}

void addExtension(spirv::Module& m, std::string_view name) {
  for (const auto& inst : m.extensions)
    if (inst.stringOperand(0) == name) return;
  m.extensions.emplace_back(spv::OpExtension, 0, 0, spirv::encodeString(name));
}

// A fresh 32-bit int interface variable, named like the GLSL built-in so the emitted text reads as
// the application's own would.
uint32_t addIntVariable(spirv::Module& m, spv::StorageClass storage, std::string_view name, bool isSigned = true) {
  uint32_t var = m.addGlobalVariable(m.typePointer(storage, m.typeInt(32, isSigned)), storage);
  m.setName(var, name);
  return var;
}

uint32_t ensureViewIndex(PassContext& ctx) {
  auto& m = ctx.module;
  if (uint32_t var = builtInVariable(m, spv::BuiltInViewIndex)) return var;
  // OpenGL's gl_ViewID_OVR is a uint (Vulkan's gl_ViewIndex an int): SPIRV-Cross writes the GLSL
  // built-in with the SPIR-V variable's type, so it must match for the comparison to compile.
  TargetLanguage target = outputLanguage(ctx);
  bool openGl = glslOutput(target) && openGlOutput(ctx, target);
  uint32_t var = addIntVariable(m, spv::StorageClassInput, "gl_ViewIndex", !openGl);
  m.decorate(var, spv::DecorationBuiltIn, {uint32_t(spv::BuiltInViewIndex)});
  // An integer fragment input must be flat (Vulkan's rule for ViewIndex in the fragment stage).
  if (m.executionModel() == spv::ExecutionModelFragment) m.decorate(var, spv::DecorationFlat);
  m.addCapability(spv::CapabilityMultiView);
  addExtension(m, "SPV_KHR_multiview");  // core from SPIR-V 1.3, still valid to name there
  return var;
}

// The instance index the shader reads (gl_InstanceIndex, OpenGL's gl_InstanceID, HLSL's
// SV_InstanceID), declared when it reads none: InstanceId for OpenGL GLSL, InstanceIndex elsewhere.
uint32_t ensureInstanceIndex(PassContext& ctx) {
  auto& m = ctx.module;
  if (uint32_t var = builtInVariable(m, spv::BuiltInInstanceIndex)) return var;
  if (uint32_t var = builtInVariable(m, spv::BuiltInInstanceId)) return var;
  bool openGl = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
  uint32_t var = addIntVariable(m, spv::StorageClassInput, openGl ? "gl_InstanceID" : "gl_InstanceIndex");
  m.decorate(var, spv::DecorationBuiltIn, {uint32_t(openGl ? spv::BuiltInInstanceId : spv::BuiltInInstanceIndex)});
  return var;
}

// The fragment stage's `flat in int stereoEye` (instanced mode), declared on first use.
uint32_t ensureEyeVaryingInput(PassContext& ctx) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassInput && m.name(inst.resultId) == o.eyeVaryingName)
      return inst.resultId;
  uint32_t var = addIntVariable(m, spv::StorageClassInput, o.eyeVaryingName);
  m.decorate(var, spv::DecorationFlat);
  m.decorate(var, spv::DecorationLocation, {o.eyeVaryingLocation});
  return var;
}

// Whether an interface variable of `storage` already sits at `location` (a clash with stereoEye).
bool locationTaken(const spirv::Module& m, spv::StorageClass storage, uint32_t location, std::string* who) {
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == uint32_t(storage) &&
        m.decorationValue(inst.resultId, spv::DecorationLocation) == location) {
      *who = m.name(inst.resultId);
      return true;
    }
  return false;
}

uint32_t emitLoad(spirv::Module& m, std::vector<Instruction>& out, uint32_t variable) {
  uint32_t value = m.takeId();
  out.emplace_back(spv::OpLoad, m.pointeeType(m.definition(variable)->typeId), value, std::vector<uint32_t>{variable});
  return value;
}

// `instance & 1`: the eye of an instanced-stereo vertex (0 for instances 0, 2, 4, ...).
uint32_t emitInstanceEyeBit(PassContext& ctx, std::vector<Instruction>& out) {
  auto& m = ctx.module;
  uint32_t variable = ensureInstanceIndex(ctx);
  uint32_t type = m.pointeeType(m.definition(variable)->typeId);  // int, or uint for HLSL's SV_InstanceID
  uint32_t instance = emitLoad(m, out, variable);
  uint32_t bit = m.takeId();
  out.emplace_back(spv::OpBitwiseAnd, type, bit, std::vector<uint32_t>{instance, m.constantInt(1)});
  const Instruction* typeDef = m.definition(type);
  if (typeDef && typeDef->operand(1) == 0) {  // HLSL's `uint id : SV_InstanceID`: the layer is an int
    uint32_t asInt = m.takeId();
    out.emplace_back(spv::OpBitcast, m.typeInt(32, true), asInt, std::vector<uint32_t>{bit});
    bit = asInt;
  }
  return bit;
}

// Refuses what the output cannot express, with the reason and what to do instead.
bool checkTarget(PassContext& ctx) {
  const EyeSelect select = ctx.options.eye.select;
  const char* flag = modeFlag(select);
  TargetLanguage target = outputLanguage(ctx);
  spv::ExecutionModel model = ctx.module.executionModel();
  bool tessOrGeometry = model == spv::ExecutionModelTessellationControl ||
                        model == spv::ExecutionModelTessellationEvaluation || model == spv::ExecutionModelGeometry;
  auto refuse = [&](const std::string& why) {
    ctx.diags.error(ctx.file, std::string(flag) + ": " + why);
    return false;
  };
  if (ctx.source.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl &&
      (model == spv::ExecutionModelGeometry || model == spv::ExecutionModelTessellationEvaluation))
    return refuse("HLSL geometry and domain shaders back to HLSL are spliced into their own text, which carries "
                  "the two-pass shift only; choose --target spirv or --target glsl");
  if (target == TargetLanguage::Msl)
    return refuse("not for --target msl (Metal draws both eyes with vertex amplification, which stereoshift does "
                  "not write yet); use two passes (--eye-source uniform-block)");
  if (glslOutput(target) && openGlOutput(ctx, target)) {
    bool es = target == TargetLanguage::Essl;
    int version = glslOutputVersion(ctx, target);
    if (version < (es ? 300 : 330))
      return refuse(std::string("needs ") + (es ? "ESSL 300" : "GLSL 330") + " or later (this output is " +
                    std::to_string(version) + (es ? " es" : "") + "); add --target-version " + (es ? "300" : "330"));
    if (select == EyeSelect::ViewIndex && tessOrGeometry)
      return refuse("OpenGL multiview (GL_OVR_multiview2) does not allow tessellation or geometry shaders in a "
                    "multiview draw; use --eye-source instanced, or a Vulkan target (--target spirv)");
    bool vertex = model == spv::ExecutionModelVertex;
    if (select == EyeSelect::InstanceIndex && es && vertex)
      return refuse("an ESSL vertex shader cannot write gl_Layer or gl_ViewportIndex; use --eye-source multiview "
                    "(GL_OVR_multiview2) for OpenGL ES");
    if (select == EyeSelect::InstanceIndex && !es && vertex && version < 410)
      return refuse("a vertex shader writes gl_Layer / gl_ViewportIndex through GL_ARB_shader_viewport_layer_array, "
                    "which needs GLSL 410 (this output is " + std::to_string(version) +
                    "); add --target-version 410, or use --eye-source multiview (GL_OVR_multiview2)");
  }
  if (select == EyeSelect::ViewIndex && target == TargetLanguage::Hlsl && ctx.options.targetVersion &&
      *ctx.options.targetVersion < 61)
    return refuse("SV_ViewID needs shader model 6.1 (this is --target-version " +
                  std::to_string(*ctx.options.targetVersion) + "); drop --target-version or give 61 or later");
  if (select == EyeSelect::InstanceIndex && ctx.classification != Classification::AlreadyStereo &&
      (tessOrGeometry || ctx.classification == Classification::Intermediate) &&
      model != spv::ExecutionModelTessellationControl)
    return refuse("the eye comes from the vertex stage's instance index, and this pipeline rasterizes after a "
                  "tessellation or geometry stage, which would have to hand it on; use --eye-source multiview");
  return true;
}

// Rewrites every read of the instance index to the original instance (`instance >> 1`).
int rewriteInstanceReads(PassContext& ctx, uint32_t instanceVariable) {
  auto& m = ctx.module;
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

// Declares the vertex stage's `flat out int stereoEye` that hands the eye to the fragment stage;
// 0 (with an error) when its location is taken.
uint32_t declareEyeVaryingOutput(PassContext& ctx, nlohmann::json& report) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  std::string who;
  if (locationTaken(m, spv::StorageClassOutput, o.eyeVaryingLocation, &who)) {
    ctx.diags.error(ctx.file, std::string(modeFlag(o.select)) + ": output location " +
                                  std::to_string(o.eyeVaryingLocation) + " of the eye varying '" + o.eyeVaryingName +
                                  "' is taken by '" + who + "'; choose a free one with --eye-varying-location");
    return 0;
  }
  uint32_t varying = addIntVariable(m, spv::StorageClassOutput, o.eyeVaryingName);
  m.decorate(varying, spv::DecorationFlat);
  m.decorate(varying, spv::DecorationLocation, {o.eyeVaryingLocation});
  report["eye_varying"] = {{"name", o.eyeVaryingName}, {"location", o.eyeVaryingLocation}};
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

// Instanced: writes the eye to the layer (or viewport index) and to the `stereoEye` varying at the
// start of the entry point.
bool routeInstancedEye(PassContext& ctx, nlohmann::json& report) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  bool layer = o.route == EyeRoute::Layer;
  if (builtInVariable(m, layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex)) {
    ctx.diags.error(ctx.file, std::string("--eye-source instanced: the shader writes ") +
                                  (layer ? "gl_Layer" : "gl_ViewportIndex") + " itself; the eye cannot be routed there "
                                  "(try --eye-route " + (layer ? "viewport" : "layer") + ")");
    return false;
  }
  uint32_t varying = declareEyeVaryingOutput(ctx, report);
  if (!varying) return false;
  uint32_t target = addIntVariable(m, spv::StorageClassOutput, layer ? "gl_Layer" : "gl_ViewportIndex");
  if (layer && outputLanguage(ctx) == TargetLanguage::Hlsl) {
    // SPIRV-Cross writes SV_RenderTargetArrayIndex from geometry shaders only (D3D12 allows it from
    // any stage that feeds the rasterizer, VPAndRTArrayIndexFromAnyShaderFeedingRasterizer): a
    // plain output carrying the semantic, which the back end puts back like any source semantic.
    m.setName(target, "stereoLayer");  // SPIRV-Cross reserves gl_ names for its built-ins
    m.decorate(target, spv::DecorationLocation, {o.eyeVaryingLocation + 1});
    m.annotations.emplace_back(spv::OpDecorateString, 0, 0, std::vector<uint32_t>{target, uint32_t(spv::DecorationUserSemantic)});
    for (uint32_t word : spirv::encodeString("SV_RenderTargetArrayIndex")) m.annotations.back().operands.push_back(word);
    addExtension(m, "SPV_GOOGLE_decorate_string");
    addExtension(m, "SPV_GOOGLE_hlsl_functionality1");
  } else {
    m.decorate(target, spv::DecorationBuiltIn, {uint32_t(layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex)});
    // Layer / ViewportIndex from the vertex stage: VK_EXT_shader_viewport_index_layer,
    // GL_ARB_shader_viewport_layer_array, D3D's SV_ViewportArrayIndex.
    m.addCapability(spv::CapabilityShaderViewportIndexLayerEXT);
    addExtension(m, "SPV_EXT_shader_viewport_index_layer");
    if (!layer) m.addCapability(spv::CapabilityMultiViewport);
  }
  std::vector<Instruction> code;
  uint32_t eye = emitInstanceEyeBit(ctx, code);
  code.emplace_back(spv::OpStore, 0, 0, std::vector<uint32_t>{target, eye});
  code.emplace_back(spv::OpStore, 0, 0, std::vector<uint32_t>{varying, eye});
  prependToEntry(m, code);
  report["eye_written_to"] = layer ? "layer" : "viewport";
  return true;
}

// OpenGL multiview: SPIRV-Cross writes gl_ViewID_OVR in vertex shaders only, so the vertex stage
// hands the view on to the fragment stage's per-eye fixes as `stereoEye`, as instanced mode does.
bool handOnViewIndex(PassContext& ctx, nlohmann::json& report) {
  auto& m = ctx.module;
  uint32_t varying = declareEyeVaryingOutput(ctx, report);
  if (!varying) return false;
  std::vector<Instruction> code;
  uint32_t viewIndex = ensureViewIndex(ctx);
  uint32_t view = emitLoad(m, code, viewIndex);
  const Instruction* type = m.definition(m.pointeeType(m.definition(viewIndex)->typeId));
  if (type && type->operand(1) == 0) {  // gl_ViewID_OVR is a uint
    uint32_t asInt = m.takeId();
    code.emplace_back(spv::OpBitcast, m.typeInt(32, true), asInt, std::vector<uint32_t>{view});
    view = asInt;
  }
  code.emplace_back(spv::OpStore, 0, 0, std::vector<uint32_t>{varying, view});
  prependToEntry(m, code);
  // GL_OVR_multiview lets only gl_Position depend on the view; this output does (and the shifted
  // halo outputs may), which GL_OVR_multiview2, the extension SPIRV-Cross declares, allows.
  report["requires"] = "GL_OVR_multiview2 (plain GL_OVR_multiview lets only gl_Position depend on the view)";
  return true;
}

// Whether the fragment stage reads the eye from the `stereoEye` varying rather than a built-in.
bool eyeFromVarying(const PassContext& ctx) {
  if (ctx.module.executionModel() != spv::ExecutionModelFragment) return false;
  if (ctx.options.eye.select == EyeSelect::InstanceIndex) return true;
  TargetLanguage target = outputLanguage(ctx);
  return glslOutput(target) && openGlOutput(ctx, target);
}

class SinglePassStereoPass final : public Pass {
 public:
  const char* name() const override { return "single-pass-stereo"; }

  PassResult run(PassContext& ctx) override {
    const EyeSelect select = ctx.options.eye.select;
    if (select == EyeSelect::Parameter) return PassResult::Unchanged;
    auto& report = ctx.report["passes"][name()];
    report["mode"] = select == EyeSelect::ViewIndex ? "multiview" : "instanced";
    if (ctx.classification == Classification::AlreadyStereo) return PassResult::Unchanged;
    if (!checkTarget(ctx)) return PassResult::Failed;
    auto& m = ctx.module;
    // A vertex shader that rasterizes, 2D ones included: instanced mode draws each twice per
    // instance, so each routes its eye whether it gets the shift or not.
    bool rasterizingVertex = m.executionModel() == spv::ExecutionModelVertex &&
                             (ctx.classification == Classification::Perspective ||
                              ctx.classification == Classification::ConstantW1 || ctx.shiftPosition);
    if (select == EyeSelect::ViewIndex) {
      TargetLanguage target = outputLanguage(ctx);
      if (rasterizingVertex && glslOutput(target) && openGlOutput(ctx, target)) {
        if (!handOnViewIndex(ctx, report)) return PassResult::Failed;
        return PassResult::Changed;
      }
      // Declared here for a shader that gets the shift (fixes of other stages declare it on use).
      if (!ctx.shiftPosition) return PassResult::Unchanged;
      ensureViewIndex(ctx);
      return PassResult::Changed;
    }
    if (!rasterizingVertex) return PassResult::Unchanged;
    uint32_t instance = ensureInstanceIndex(ctx);
    report["instance_reads_rewritten"] = rewriteInstanceReads(ctx, instance);
    if (!routeInstancedEye(ctx, report)) return PassResult::Failed;
    return PassResult::Changed;
  }
};

}  // namespace

uint32_t emitDerivedEyeSign(PassContext& ctx, std::vector<Instruction>& out) {
  auto& m = ctx.module;
  uint32_t eye = 0;  // an int that is 0 for the first eye (view 0, even instances)
  if (eyeFromVarying(ctx)) {
    eye = emitLoad(m, out, ensureEyeVaryingInput(ctx));
  } else if (ctx.options.eye.select == EyeSelect::ViewIndex) {
    eye = emitLoad(m, out, ensureViewIndex(ctx));
  } else {
    eye = emitInstanceEyeBit(ctx, out);
  }
  uint32_t second = m.takeId();
  out.emplace_back(spv::OpINotEqual, m.typeBool(), second, std::vector<uint32_t>{eye, m.constantInt(0)});
  // Exactly -1 and +1, the values a two-pass draw sets: the shift is the same arithmetic, bit for bit.
  float secondSign = ctx.options.eye.swapEyes ? -1.0f : 1.0f;
  uint32_t sign = m.takeId();
  out.emplace_back(spv::OpSelect, m.typeFloat(32), sign,
                   std::vector<uint32_t>{second, m.constantFloat(secondSign), m.constantFloat(-secondSign)});
  return sign;
}

std::unique_ptr<Pass> createSinglePassStereoPass() { return std::make_unique<SinglePassStereoPass>(); }

}  // namespace stereoshift
