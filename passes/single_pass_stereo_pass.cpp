// single-pass-stereo: turns a mono shader into one that draws both eyes in one pass
// (--eye-source multiview | instanced). The shift itself stays stereo-shift's; what changes is where
// eyeSign comes from, and this file is the one place that says so (emitDerivedEyeSign, which
// emitLoadEyeParam calls for eyeSign in these modes):
//   multiview: the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID), view 0 the left eye;
//   instanced: the low bit of the instance index in the vertex stage (the application doubles the
//     instance count); every later stage reads the varying `stereoEye` the stage before it wrote (the
//     fragment stage too, also for OpenGL multiview, where SPIRV-Cross writes gl_ViewID_OVR in vertex
//     shaders only). Between pre-rasterization stages it is `stereoEyeStage`, through tessellation
//     `patch out int stereoEyePatch` (every vertex of a patch comes from one instance); tessellation
//     control and geometry stages read element 0 of their per-vertex input array.
// The pass itself checks that the output language can express the mode (refusing with the reason
// and what to do instead), declares the view index of a multiview shader that gets the shift, and
// in instanced mode rewrites the vertex shader: every use of the instance index reads the original
// instance (`instance >> 1`), and the eye goes to the `stereoEye` varying and, from the stage that
// rasterizes (vertex, tessellation evaluation or geometry), to the render-target layer or the
// viewport index; the stages between hand it on.
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

// Whether the per-vertex interface of this stage wraps `storage` variables in an outer array
// (tessellation and geometry inputs, tessellation control outputs), which takes no locations.
bool perVertexArrayed(const spirv::Module& m, spv::StorageClass storage, uint32_t variable) {
  if (m.hasDecoration(variable, spv::DecorationPatch)) return false;
  switch (m.executionModel()) {
    case spv::ExecutionModelTessellationControl: return true;
    case spv::ExecutionModelTessellationEvaluation:
    case spv::ExecutionModelGeometry: return storage == spv::StorageClassInput;
    default: return false;
  }
}

// Whether an interface variable of `storage` already takes `location` (a clash with stereoEye): a
// variable whose locations (a matrix, an array, a struct take several) cover it, or a block member
// placed there.
bool locationTaken(const spirv::Module& m, spv::StorageClass storage, uint32_t location, std::string* who) {
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != uint32_t(storage)) continue;
    uint32_t type = m.pointeeType(inst.typeId);
    const Instruction* def = m.definition(type);
    if (def && def->opcode == spv::OpTypeArray && perVertexArrayed(m, storage, inst.resultId)) {
      type = def->operand(0);
      def = m.definition(type);
    }
    if (auto first = m.decorationValue(inst.resultId, spv::DecorationLocation)) {
      if (location >= *first && location < *first + spirv::interfaceLocationCount(m, type)) {
        *who = m.name(inst.resultId);
        return true;
      }
      continue;
    }
    if (!def || def->opcode != spv::OpTypeStruct) continue;
    for (uint32_t member = 0; member < def->operands.size(); ++member)
      if (auto first = m.memberDecorationValue(type, member, spv::DecorationLocation);
          first && location >= *first && location < *first + spirv::interfaceLocationCount(m, def->operands[member])) {
        *who = m.name(inst.resultId) + "." + m.memberName(type, member);
        return true;
      }
  }
  return false;
}

// How the eye varying is declared in this stage, for `storage`: per vertex in an array (the inputs
// of tessellation control and geometry shaders), per patch (tessellation control out, evaluation
// in), or a plain int, flat where it feeds or is the fragment stage's interpolated input.
struct EyeVaryingShape {
  uint32_t arrayLength = 0;  // 0: not an array
  bool patch = false;
  bool flat = false;
};

// The vertex count of a geometry shader's input primitive (the length of its per-vertex arrays).
uint32_t geometryInputVertices(const spirv::Module& m) {
  for (const auto& inst : m.executionModes) {
    switch (inst.operand(1)) {
      case spv::ExecutionModeInputPoints: return 1;
      case spv::ExecutionModeInputLines: return 2;
      case spv::ExecutionModeInputLinesAdjacency: return 4;
      case spv::ExecutionModeTriangles: return 3;
      case spv::ExecutionModeInputTrianglesAdjacency: return 6;
      default: break;
    }
  }
  return 3;
}

// The length glslang gives the per-vertex input arrays of a tessellation control shader (that of
// gl_in, gl_MaxPatchVertices when unsized): taken from an input array already declared, else 32.
uint32_t tessControlInputLength(const spirv::Module& m) {
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassInput) continue;
    const Instruction* type = m.definition(m.pointeeType(inst.typeId));
    if (type && type->opcode == spv::OpTypeArray)
      if (const Instruction* length = m.definition(type->operand(1)); length && length->opcode == spv::OpConstant)
        return length->operand(0);
  }
  return 32;
}

EyeVaryingShape eyeVaryingShape(const spirv::Module& m, spv::StorageClass storage) {
  bool input = storage == spv::StorageClassInput;
  switch (m.executionModel()) {
    case spv::ExecutionModelTessellationControl:
      return input ? EyeVaryingShape{tessControlInputLength(m), false, false} : EyeVaryingShape{0, true, false};
    case spv::ExecutionModelTessellationEvaluation:
      return input ? EyeVaryingShape{0, true, false} : EyeVaryingShape{0, false, true};
    case spv::ExecutionModelGeometry:
      return input ? EyeVaryingShape{geometryInputVertices(m), false, false} : EyeVaryingShape{0, false, true};
    default:  // vertex out, fragment in
      return EyeVaryingShape{0, false, true};
  }
}

// The name of the eye varying on one side of a stage: `stereoEye` (--eye-varying-name) into the
// fragment stage, `stereoEyeStage` between two pre-rasterization stages, `stereoEyePatch` per patch.
// OpenGL below GLSL 410 matches varyings by name, and a stage's input and output cannot share one.
std::string eyeVaryingName(const PassContext& ctx, spv::StorageClass storage) {
  const std::string& base = ctx.options.eye.eyeVaryingName;
  bool input = storage == spv::StorageClassInput;
  bool feedsStage = ctx.classification == Classification::Intermediate;
  switch (ctx.module.executionModel()) {
    case spv::ExecutionModelVertex: return feedsStage ? base + "Stage" : base;
    case spv::ExecutionModelTessellationControl: return input ? base + "Stage" : base + "Patch";
    case spv::ExecutionModelTessellationEvaluation: return input ? base + "Patch" : feedsStage ? base + "Stage" : base;
    case spv::ExecutionModelGeometry: return input ? base + "Stage" : base;
    default: return base;
  }
}

// The eye varying of this stage (`storage` Input: what the stage before wrote, Output: what this
// stage hands on), declared on first use at --eye-varying-location. 0 (with an error) when another
// variable already takes the location.
uint32_t ensureEyeVarying(PassContext& ctx, spv::StorageClass storage) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  const std::string name = eyeVaryingName(ctx, storage);
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == uint32_t(storage) && m.name(inst.resultId) == name &&
        m.decorationValue(inst.resultId, spv::DecorationLocation) == o.eyeVaryingLocation)
      return inst.resultId;
  std::string who;
  if (locationTaken(m, storage, o.eyeVaryingLocation, &who)) {
    ctx.diags.error(ctx.file, std::string(modeFlag(o.select)) + ": " + (storage == spv::StorageClassInput ? "input" : "output") + " location " +
                                  std::to_string(o.eyeVaryingLocation) + " of the eye varying '" + name +
                                  "' is taken by '" + (who.empty() ? std::string("an unnamed variable") : who) +
                                  "'; choose a location free in every stage with --eye-varying-location");
    return 0;
  }
  EyeVaryingShape shape = eyeVaryingShape(m, storage);
  uint32_t type = m.typeInt(32, true);
  if (shape.arrayLength) type = m.typeArray(type, shape.arrayLength);
  uint32_t var = m.addGlobalVariable(m.typePointer(storage, type), storage);
  m.setName(var, name);
  if (shape.flat) m.decorate(var, spv::DecorationFlat);
  if (shape.patch) m.decorate(var, spv::DecorationPatch);
  m.decorate(var, spv::DecorationLocation, {o.eyeVaryingLocation});
  return var;
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
  if (ctx.source.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl &&
      (model == spv::ExecutionModelGeometry || model == spv::ExecutionModelTessellationEvaluation))
    return refuse("HLSL geometry and domain shaders back to HLSL are spliced into their own text, which carries "
                  "the two-pass shift only; choose --target spirv or --target glsl");
  // Instanced mode hands the eye on through the hull shader, which SPIRV-Cross cannot write as HLSL
  // (in two passes a hull shader is copied unchanged).
  if (instanced && ctx.source.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl &&
      model == spv::ExecutionModelTessellationControl)
    return refuse("the eye is handed on through the hull shader, and HLSL hull shaders cannot be re-emitted as "
                  "HLSL; choose --target spirv or --target glsl");

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
  if (select == EyeSelect::ViewIndex && target == TargetLanguage::Hlsl && ctx.options.targetVersion &&
      *ctx.options.targetVersion < 61)
    return refuse("SV_ViewID needs shader model 6.1 (this is --target-version " +
                  std::to_string(*ctx.options.targetVersion) + "); drop --target-version or give 61 or later");
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
uint32_t declareEyeVaryingOutput(PassContext& ctx, nlohmann::json& report) {
  const auto& o = ctx.options.eye;
  uint32_t varying = ensureEyeVarying(ctx, spv::StorageClassOutput);
  if (varying) report["eye_varying"] = {{"name", eyeVaryingName(ctx, spv::StorageClassOutput)}, {"location", o.eyeVaryingLocation}};
  return varying;
}

// Loads the eye the stage before wrote into this stage's `stereoEye` input (element 0 of a
// per-vertex array: every vertex of a primitive or patch comes from one instance). 0 on a location clash.
uint32_t emitLoadHandedOnEye(PassContext& ctx, std::vector<Instruction>& out) {
  auto& m = ctx.module;
  uint32_t input = ensureEyeVarying(ctx, spv::StorageClassInput);
  if (!input) return 0;
  const Instruction* type = m.definition(m.pointeeType(m.definition(input)->typeId));
  if (!type || type->opcode != spv::OpTypeArray) return emitLoad(m, out, input);
  uint32_t element = type->operand(0);
  uint32_t pointer = m.takeId();
  out.emplace_back(spv::OpAccessChain, m.typePointer(spv::StorageClassInput, element), pointer,
                   std::vector<uint32_t>{input, m.constantInt(0)});
  uint32_t value = m.takeId();
  out.emplace_back(spv::OpLoad, element, value, std::vector<uint32_t>{pointer});
  return value;
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
    m.annotations.emplace_back(spv::OpDecorateString, 0, 0, std::vector<uint32_t>{target, uint32_t(spv::DecorationUserSemantic)});
    for (uint32_t word : spirv::encodeString("SV_RenderTargetArrayIndex")) m.annotations.back().operands.push_back(word);
    addExtension(m, "SPV_GOOGLE_decorate_string");
    addExtension(m, "SPV_GOOGLE_hlsl_functionality1");
    return target;
  }
  m.decorate(target, spv::DecorationBuiltIn, {uint32_t(layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex)});
  if (!layer) m.addCapability(spv::CapabilityMultiViewport);
  if (!geometry) {
    // Layer / ViewportIndex from the vertex or tessellation evaluation stage:
    // VK_EXT_shader_viewport_index_layer, GL_ARB_shader_viewport_layer_array, D3D's SV_ViewportArrayIndex.
    // A geometry shader writes both natively (capability Geometry).
    m.addCapability(spv::CapabilityShaderViewportIndexLayerEXT);
    addExtension(m, "SPV_EXT_shader_viewport_index_layer");
  }
  return target;
}

// Instanced: the eye (the instance's low bit in the vertex stage, the handed-on varying after it)
// goes to the `stereoEye` output and, in the stage that rasterizes, to the layer or viewport index:
// at the start of the entry point, or before every emit of a geometry shader.
bool routeInstancedEye(PassContext& ctx, nlohmann::json& report) {
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
  uint32_t varying = declareEyeVaryingOutput(ctx, report);
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
    if (target) code.emplace_back(spv::OpStore, 0, 0, std::vector<uint32_t>{target, eye});
    code.emplace_back(spv::OpStore, 0, 0, std::vector<uint32_t>{varying, eye});
    return code;
  };
  if (model == spv::ExecutionModelGeometry) {
    report["emits_routed"] = insertBeforeEachEmit(m, storeEye);
  } else {
    prependToEntry(m, storeEye());
  }
  if (failed) return false;
  if (target) report["eye_written_to"] = layer ? "layer" : "viewport";
  else report["eye_handed_on"] = true;
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

// Whether this stage reads the eye from the `stereoEye` varying rather than a built-in: every stage
// after the vertex stage in instanced mode, the fragment stage of OpenGL multiview.
bool eyeFromVarying(const PassContext& ctx) {
  spv::ExecutionModel model = ctx.module.executionModel();
  if (ctx.options.eye.select == EyeSelect::InstanceIndex)
    return model != spv::ExecutionModelVertex;
  if (model != spv::ExecutionModelFragment) return false;
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
    spv::ExecutionModel model = m.executionModel();
    if (select == EyeSelect::ViewIndex) {
      TargetLanguage target = outputLanguage(ctx);
      if (model == spv::ExecutionModelVertex && rasterizingStage(ctx) && glslOutput(target) && openGlOutput(ctx, target)) {
        if (!handOnViewIndex(ctx, report)) return PassResult::Failed;
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
      report["instance_reads_rewritten"] = rewritten;
    }
    if (!routeInstancedEye(ctx, report)) return PassResult::Failed;
    return PassResult::Changed;
  }
};

}  // namespace

uint32_t emitDerivedEyeSign(PassContext& ctx, std::vector<Instruction>& out) {
  auto& m = ctx.module;
  uint32_t eye = 0;  // an int that is 0 for the first eye (view 0, even instances)
  if (eyeFromVarying(ctx)) {
    eye = emitLoadHandedOnEye(ctx, out);
    if (!eye) eye = m.constantInt(0);  // the location clash is reported; the conversion fails
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

std::optional<int> singlePassRaisedGlslVersion(const SourceInfo& source, const TranspileOptions& options,
                                               std::string* why) {
  const auto& eye = options.eye;
  if (eye.select == EyeSelect::Parameter || options.targetVersion || source.compatibilityBuiltIns) return std::nullopt;
  bool keptAsGlsl = options.target == TargetLanguage::Auto || options.target == TargetLanguage::Glsl;
  if (source.language != SourceLanguage::Glsl || source.es || source.vulkan || !keptAsGlsl) return std::nullopt;
  bool last = options.shiftThisStage;  // the stage that rasterizes
  int needed = 0;
  if (eye.select == EyeSelect::ViewIndex) {
    if (source.stage == Stage::Vertex) {
      needed = 330;
      *why = "GL_OVR_multiview2 needs GLSL 330";
    }
  } else if ((source.stage == Stage::Vertex || source.stage == Stage::TessEvaluation) && last) {
    needed = 410;
    *why = "the eye is written to gl_Layer / gl_ViewportIndex from this stage through "
           "GL_ARB_shader_viewport_layer_array, which needs GLSL 410";
  } else if (source.stage == Stage::Vertex) {
    needed = 330;
    *why = "the eye is handed to the next stage as a flat int varying";
  } else if (source.stage == Stage::Geometry && eye.route == EyeRoute::Viewport) {
    needed = 410;
    *why = "a geometry shader writes gl_ViewportIndex from GLSL 410";
  }
  if (!needed || source.version >= needed) return std::nullopt;
  return needed;
}

std::unique_ptr<Pass> createSinglePassStereoPass() { return std::make_unique<SinglePassStereoPass>(); }

}  // namespace stereoshift
