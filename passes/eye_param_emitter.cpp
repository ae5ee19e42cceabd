// See eye_param_emitter.h: the one place that declares the eye parameters (as a uniform block /
// cbuffer, push-constant members, loose OpenGL uniforms or specialization constants, names that
// clash with the application's own renamed and recorded) and loads them.
#include "passes/eye_param_emitter.h"

#include "passes/eye_select.h"
#include "passes/ir/builder.h"
#include "passes/pass.h"
#include "passes/shift_emitter.h"

#include <algorithm>
#include <set>

namespace stereoshift {

using spirv::Instruction;

namespace {

bool usesLooseUniforms(const spirv::Module& m) {
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassUniformConstant &&
        !m.isOpaqueType(m.pointeeType(inst.typeId)))
      return true;
  return false;
}

// Byte size of a type laid out with explicit Offset / ArrayStride / MatrixStride decorations.
uint32_t explicitSize(const spirv::Module& m, uint32_t type) {
  const Instruction* def = m.definition(type);
  if (!def) return 0;
  switch (def->opcode) {
    case spv::OpTypeBool: return 4;
    case spv::OpTypeInt: case spv::OpTypeFloat: return def->operand(0) / 8;
    case spv::OpTypeVector: return def->operand(1) * explicitSize(m, def->operand(0));
    case spv::OpTypeMatrix: {
      uint32_t columns = def->operand(1);
      // MatrixStride lives on the struct member; assume tightly packed vec4 columns otherwise.
      return columns * 16;
    }
    case spv::OpTypeArray: {
      const Instruction* length = m.definition(def->operand(1));
      uint32_t count = length ? length->operand(0) : 1;
      uint32_t stride = m.decorationValue(type, spv::DecorationArrayStride).value_or(explicitSize(m, def->operand(0)));
      return count * stride;
    }
    case spv::OpTypeStruct: {
      uint32_t end = 0;
      for (uint32_t i = 0; i < def->operands.size(); ++i) {
        uint32_t offset = m.memberDecorationValue(type, i, spv::DecorationOffset).value_or(0);
        uint32_t size = explicitSize(m, def->operands[i]);
        if (auto stride = m.memberDecorationValue(type, i, spv::DecorationMatrixStride)) {
          const Instruction* member = m.definition(def->operands[i]);
          if (member && member->opcode == spv::OpTypeMatrix) size = member->operand(1) * *stride;
        }
        end = std::max(end, offset + size);
      }
      return end;
    }
    default: return 0;
  }
}

uint32_t firstFreeUniformLocation(const spirv::Module& m) {
  uint32_t next = 0;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassUniformConstant)
      if (auto loc = m.decorationValue(inst.resultId, spv::DecorationLocation)) next = std::max(next, *loc + 16);
  return next;
}

// The binding for the new block: the option, else one past the highest binding in the set. D3D-style
// HLSL registers are per class (b, t, s, u), so there only constant buffers count.
uint32_t chooseBinding(const PassContext& ctx, uint32_t set) {
  const auto& o = ctx.options.eye;
  if (ctx.source.language == SourceLanguage::Hlsl && o.hlslRegister) return *o.hlslRegister;
  if (o.binding) return *o.binding;
  auto highest = highestBinding(ctx.module, set, perClassRegisters(ctx.source));
  return highest ? *highest + 1 : 0;
}

const std::string& wantedName(const EyeParamOptions& o, int which) {
  switch (which) {
    case kEyeSign: return o.eyeSignName;
    case kSeparation: return o.separationName;
    case kConvergence: return o.convergenceName;
    case kHudDepth: return o.hudDepthName;
    case kEyeOffsetX: return o.eyeOffsetXName;
    case kEyeOffsetY: return o.eyeOffsetYName;
    case kProjScaleX: return o.projScaleXName;
    default: return o.eyeOffsetZName;
  }
}

// Mono until the application sets them: eyeSign 0, convergence 1, HUD at depth 1, no offset.
float defaultValue(int which) {
  return which == kConvergence || which == kHudDepth || which == kProjScaleX ? 1.0f : 0.0f;
}

// Picks the source and checks it fits the shader; the first declaration only.
bool chooseSource(PassContext& ctx) {
  EyeSource source = ctx.options.eye.source;
  auto& m = ctx.module;
  bool gl = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
  if (source == EyeSource::Auto) source = gl && usesLooseUniforms(m) ? EyeSource::LooseUniforms : EyeSource::UniformBlock;
  if (source == EyeSource::LooseUniforms && !gl) {
    ctx.diags.error(ctx.file, "--eye-source=loose-uniforms needs an OpenGL GLSL shader; Vulkan and HLSL have "
                              "no default-block uniforms (use uniform-block, push-constant or spec-constant)");
    return false;
  }
  if (source == EyeSource::PushConstant && gl) {
    ctx.diags.error(ctx.file, "--eye-source=push-constant needs a Vulkan shader; this is OpenGL GLSL");
    return false;
  }
  ctx.eye.source = source;
  if (ctx.options.compensatedShift && ctx.shiftPosition && !targetSupportsPrecise(ctx))
    ctx.diags.warning(ctx.file, "--compensated-shift needs `precise`, which this output language lacks: a "
                                "driver may contract or re-associate the error-free arithmetic");
  return true;
}

// Chooses names for params [from, to): clashes with the shader's own names get a suffix (and a
// warning). Block members are scoped by the instance, except HLSL cbuffer members and loose uniforms.
void chooseNames(PassContext& ctx, int from, int to) {
  EyeParamFacts& facts = ctx.record.eyeParams;
  EyeSource source = ctx.eye.source;
  bool global = source == EyeSource::LooseUniforms || source == EyeSource::SpecConstant ||
                ctx.source.language == SourceLanguage::Hlsl;
  std::set<std::string> taken;
  for (const auto& n : ctx.module.allNames()) taken.insert(n);
  for (int i = 0; i < from; ++i) taken.insert(ctx.eye.names[i]);
  for (int i = from; i < to; ++i) {
    const std::string& wanted = wantedName(ctx.options.eye, i);
    std::string chosen = wanted;
    if (global)
      for (int k = 1; taken.count(chosen); ++k) chosen = wanted + "_stereo" + (k > 1 ? std::to_string(k) : "");
    if (chosen != wanted) {
      ctx.diags.warning(ctx.file, "the shader already declares '" + wanted + "'; the injected one is named '" +
                                      chosen + "'");
      facts.renamed[wanted] = chosen;
    }
    taken.insert(chosen);
    ctx.eye.names[i] = chosen;
  }
}

// Appends params [from, to) as float members of the eye block (fresh or the shader's own push
// constants): member firstMember+i at byte offset firstOffset+4*i.
void appendMembers(PassContext& ctx, int from, int to) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32);
  for (auto& t : m.typesValues)
    if (t.resultId == ctx.eye.blockType) {
      for (int i = from; i < to; ++i) t.operands.push_back(f);
      break;
    }
  m.invalidateDefinitions();
  for (int i = from; i < to; ++i) {
    uint32_t member = ctx.eye.firstMember + static_cast<uint32_t>(i);
    m.setMemberName(ctx.eye.blockType, member, ctx.eye.names[i]);
    m.decorateMember(ctx.eye.blockType, member, spv::DecorationOffset, {ctx.eye.firstOffset + 4u * i});
  }
}

// Declares a fresh block (uniform block / cbuffer, or a push-constant block when the shader has none).
void declareBlock(PassContext& ctx, spv::StorageClass storage) {
  auto& m = ctx.module;
  const auto& o = ctx.options.eye;
  ctx.eye.blockType = m.newStruct({});
  std::set<std::string> taken;
  for (const auto& n : m.allNames()) taken.insert(n);
  auto isTaken = [&](const std::string& name) { return taken.count(name) > 0; };
  std::string blockName = numberedName(o.blockName, isTaken), instanceName = numberedName(o.instanceName, isTaken);
  EyeParamFacts& facts = ctx.record.eyeParams;
  for (const auto& [wanted, chosen] : {std::pair{o.blockName, blockName}, std::pair{o.instanceName, instanceName}})
    if (wanted != chosen) {
      ctx.diags.warning(ctx.file, "the shader already declares '" + wanted + "'; the injected block uses '" +
                                      chosen + "'");
      facts.renamed[wanted] = chosen;
    }
  m.setName(ctx.eye.blockType, blockName);
  m.decorate(ctx.eye.blockType, spv::DecorationBlock);
  uint32_t var = m.addGlobalVariable(m.typePointer(storage, ctx.eye.blockType), storage);
  m.setName(var, instanceName);
  if (storage == spv::StorageClassUniform) {
    bool gl = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
    uint32_t set = o.descriptorSet.value_or(0);
    uint32_t binding = gl ? o.glBinding.value_or(chooseBinding(ctx, set)) : chooseBinding(ctx, set);
    m.decorate(var, spv::DecorationDescriptorSet, {set});
    m.decorate(var, spv::DecorationBinding, {binding});
  }
  ctx.eye.variable = var;
  ctx.eye.firstMember = 0;
  ctx.eye.firstOffset = 0;
}

// Uses the shader's own push-constant block (one per entry point allowed): the parameters go after
// its last member, 4-byte aligned.
bool useShaderPushConstants(PassContext& ctx) {
  auto& m = ctx.module;
  for (auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassPushConstant) continue;
    uint32_t structType = m.pointeeType(inst.typeId);
    // Struct types are not shared between variables in glslang output; it is extended in place.
    ctx.eye.variable = inst.resultId;
    ctx.eye.blockType = structType;
    ctx.eye.firstOffset = (explicitSize(m, structType) + 3) & ~3u;
    const Instruction* def = m.definition(structType);
    ctx.eye.firstMember = def ? static_cast<uint32_t>(def->operands.size()) : 0;
    return true;
  }
  return false;
}

}  // namespace

bool ensureEyeParams(PassContext& ctx, int count) {
  count = std::min<int>(count, kEyeParamCount);
  int from = ctx.eyeDeclared ? ctx.eye.declared : 0;
  if (count <= from) return true;
  auto& m = ctx.module;
  EyeParamFacts& facts = ctx.record.eyeParams;
  if (!ctx.eyeDeclared) {
    if (!chooseSource(ctx)) return false;
    switch (ctx.eye.source) {
      case EyeSource::LooseUniforms: facts.declared = "loose uniforms"; break;
      case EyeSource::SpecConstant: facts.declared = "specialization constants"; break;
      case EyeSource::PushConstant:
        if (!useShaderPushConstants(ctx)) declareBlock(ctx, spv::StorageClassPushConstant);
        facts.declared = "push constants";
        facts.pushConstantOffset = ctx.eye.firstOffset;
        break;
      default: {
        declareBlock(ctx, spv::StorageClassUniform);
        facts.declared = "uniform block";
        facts.block = m.name(ctx.eye.blockType);
        facts.instance = m.name(ctx.eye.variable);
        if (auto set = m.decorationValue(ctx.eye.variable, spv::DecorationDescriptorSet)) facts.set = *set;
        bool gl = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
        if (auto b = m.decorationValue(ctx.eye.variable, spv::DecorationBinding); b && (!gl || ctx.options.eye.glBinding))
          facts.binding = *b;  // OpenGL blocks without --gl-binding are bound by name
        break;
      }
    }
  }
  chooseNames(ctx, from, count);
  uint32_t f = m.typeFloat(32);
  switch (ctx.eye.source) {
    case EyeSource::LooseUniforms: {
      uint32_t pointer = m.typePointer(spv::StorageClassUniformConstant, f);
      uint32_t nextLocation = firstFreeUniformLocation(m);
      for (int i = from; i < count; ++i) {
        uint32_t var = m.addGlobalVariable(pointer, spv::StorageClassUniformConstant);
        m.setName(var, ctx.eye.names[i]);
        m.decorate(var, spv::DecorationLocation, {nextLocation + i - from});  // for validation; not emitted
        ctx.eye.looseVariables[i] = var;
      }
      break;
    }
    case EyeSource::SpecConstant: {
      for (int i = from; i < count; ++i) {
        uint32_t id = m.specConstantFloat(defaultValue(i));
        m.setName(id, ctx.eye.names[i]);
        m.decorate(id, spv::DecorationSpecId, {ctx.options.eye.specIdBase + i});
        ctx.eye.specConstants[i] = id;
      }
      facts.specIds.clear();
      for (int i = 0; i < count; ++i) facts.specIds.push_back(ctx.options.eye.specIdBase + i);
      break;
    }
    default:
      appendMembers(ctx, from, count);
      break;
  }
  facts.names.assign(ctx.eye.names, ctx.eye.names + count);
  ctx.eye.declared = count;
  ctx.eyeDeclared = true;
  return true;
}

float eyeParamDefaultValue(int which) { return defaultValue(which); }

namespace {

// The load of a declared eye parameter from where eye-params put it.
uint32_t emitLoadDeclaredEyeParam(PassContext& context, std::vector<Instruction>& out, int which) {
  auto& m = context.module;
  const EyeParams& eye = context.eye;
  uint32_t floatType = m.typeFloat(32);
  switch (eye.source) {
    case EyeSource::SpecConstant:
      return eye.specConstants[which];
    case EyeSource::LooseUniforms: {
      return spirv::Builder(m, out).load(floatType, eye.looseVariables[which]);
    }
    case EyeSource::UniformBlock:
    case EyeSource::PushConstant:
    case EyeSource::Auto: {
      auto storage = eye.source == EyeSource::PushConstant ? spv::StorageClassPushConstant
                                                           : spv::StorageClassUniform;
      uint32_t pointerType = m.typePointer(storage, floatType);
      uint32_t index = m.constantInt(static_cast<int32_t>(eye.firstMember + which));
      spirv::Builder b(m, out);
      uint32_t pointer = b.add(spv::OpAccessChain, pointerType, {eye.variable, index});
      return b.load(floatType, pointer);
    }
  }
  return 0;
}

}  // namespace

uint32_t emitLoadEyeParam(PassContext& context, std::vector<Instruction>& out, int which) {
  if (context.options.eye.select == EyeSelect::Parameter) return emitLoadDeclaredEyeParam(context, out, which);
  // Single-pass stereo: eyeSign comes from the view or the instance, not from a parameter; the eye
  // offset, one value for both eyes, is the right eye's, scaled by the eye sign (it is e*S*C/P00
  // along the camera's right axis, odd in e).
  if (which == kEyeSign) return emitDerivedEyeSign(context, out);
  uint32_t value = emitLoadDeclaredEyeParam(context, out, which);
  if (which != kEyeOffsetX && which != kEyeOffsetY && which != kEyeOffsetZ) return value;
  uint32_t sign = emitDerivedEyeSign(context, out);
  spirv::Builder b(context.module, out);
  uint32_t scaled = b.reserveId();
  return b.addAs(scaled, spv::OpFMul, context.module.typeFloat(32), {sign, value});
}

std::string numberedName(const std::string& wanted, const std::function<bool(const std::string&)>& taken) {
  std::string name = wanted;
  for (int i = 2; taken(name); ++i) name = wanted + std::to_string(i);
  return name;
}

}  // namespace stereoshift
