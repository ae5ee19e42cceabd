// See eye_select.h.
#include "passes/eye_select.h"

#include "passes/ir/builder.h"
#include "passes/pass.h"

#include <string_view>

namespace stereoshift {

using spirv::Instruction;

bool glslOutput(TargetLanguage t) { return t == TargetLanguage::Glsl || t == TargetLanguage::Essl; }

// The output language, as the back end will resolve it (Auto: the input's own).
TargetLanguage outputLanguage(const PassContext& ctx) {
  if (ctx.output.language != TargetLanguage::Auto) return ctx.output.language;
  switch (ctx.source.language) {
    case SourceLanguage::Hlsl: return TargetLanguage::Hlsl;
    case SourceLanguage::Spirv: return TargetLanguage::Spirv;
    case SourceLanguage::Glsl: return ctx.source.es ? TargetLanguage::Essl : TargetLanguage::Glsl;
  }
  return TargetLanguage::Glsl;
}

// Whether a GLSL/ESSL output has OpenGL (not Vulkan) semantics, as the back end decides it.
bool openGlOutput(const PassContext& ctx, TargetLanguage target) {
  return glslOutput(target) && !vulkanGlslOutput(ctx.source, target == TargetLanguage::Essl, ctx.output.version);
}

// The GLSL/ESSL version the output will have.
int glslOutputVersion(const PassContext& ctx, TargetLanguage target) {
  bool es = target == TargetLanguage::Essl;
  bool sameDialect = ctx.source.language == SourceLanguage::Glsl && es == ctx.source.es;
  return ctx.output.version.value_or(sameDialect ? ctx.source.version : (es ? 310 : 450));
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

// A fresh 32-bit int interface variable, named like the GLSL built-in so the emitted text reads as
// the application's own would.
uint32_t addIntVariable(spirv::Module& m, spv::StorageClass storage, std::string_view name, bool isSigned) {
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
  m.addExtension("SPV_KHR_multiview");  // core from SPIR-V 1.3, still valid to name there
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

namespace {

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

}  // namespace

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

namespace {

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

}  // namespace

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
  return spirv::Builder(m, out).load(m.pointeeType(m.definition(variable)->typeId), variable);
}

// `instance & 1`: the eye of an instanced-stereo vertex (0 for instances 0, 2, 4, ...).
uint32_t emitInstanceEyeBit(PassContext& ctx, std::vector<Instruction>& out) {
  auto& m = ctx.module;
  uint32_t variable = ensureInstanceIndex(ctx);
  uint32_t type = m.pointeeType(m.definition(variable)->typeId);  // int, or uint for HLSL's SV_InstanceID
  uint32_t instance = emitLoad(m, out, variable);
  spirv::Builder b(m, out);
  uint32_t bit = b.reserveId();
  b.addAs(bit, spv::OpBitwiseAnd, type, {instance, m.constantInt(1)});
  const Instruction* typeDef = m.definition(type);
  if (typeDef && typeDef->operand(1) == 0) {  // HLSL's `uint id : SV_InstanceID`: the layer is an int
    uint32_t asInt = b.reserveId();
    bit = b.addAs(asInt, spv::OpBitcast, m.typeInt(32, true), {bit});
  }
  return bit;
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
  spirv::Builder b(m, out);
  uint32_t pointer = b.reserveId();
  b.addAs(pointer, spv::OpAccessChain, m.typePointer(spv::StorageClassInput, element), {input, m.constantInt(0)});
  return b.load(element, pointer);
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
  spirv::Builder b(m, out);
  uint32_t second = b.reserveId();
  b.addAs(second, spv::OpINotEqual, m.typeBool(), {eye, m.constantInt(0)});
  // Exactly -1 and +1, the values a two-pass draw sets: the shift is the same arithmetic, bit for bit.
  float secondSign = ctx.options.eye.swapEyes ? -1.0f : 1.0f;
  uint32_t sign = b.reserveId();
  return b.addAs(sign, spv::OpSelect, m.typeFloat(32), {second, m.constantFloat(secondSign), m.constantFloat(-secondSign)});
}

}  // namespace stereoshift
