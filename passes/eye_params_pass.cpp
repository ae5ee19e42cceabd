// eye-params: turns a shader that needs the shift into one that declares the eye parameters
// (eyeSign, separation, convergence) as a uniform block / cbuffer, push-constant members, loose
// OpenGL uniforms or specialization constants. Names that clash with the application's own are
// renamed (and reported), never aliased.
#include "passes/pass.h"

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

class EyeParamsPass final : public Pass {
 public:
  const char* name() const override { return "eye-params"; }

  PassResult run(PassContext& ctx) override {
    if (ctx.classification != Classification::Perspective) return PassResult::Unchanged;
    auto& m = ctx.module;
    auto& report = ctx.report["passes"][name()];
    const EyeParamOptions& o = ctx.options.eye;

    EyeSource source = o.source;
    if (source == EyeSource::Auto)
      source = (ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan && usesLooseUniforms(m))
                   ? EyeSource::LooseUniforms
                   : EyeSource::UniformBlock;
    if (source == EyeSource::LooseUniforms && !(ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan)) {
      ctx.diags.error(ctx.file, "--eye-source=loose-uniforms needs an OpenGL GLSL shader; Vulkan and HLSL have "
                                "no default-block uniforms (use uniform-block, push-constant or spec-constant)");
      return PassResult::Failed;
    }
    if (source == EyeSource::PushConstant && ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan) {
      ctx.diags.error(ctx.file, "--eye-source=push-constant needs a Vulkan shader; this is OpenGL GLSL");
      return PassResult::Failed;
    }
    ctx.eye.source = source;
    if (ctx.options.compensatedShift && !targetSupportsPrecise(ctx))
      ctx.diags.warning(ctx.file, "--compensated-shift needs `precise`, which this output language lacks: a "
                                  "driver may contract or re-associate the error-free arithmetic");

    std::set<std::string> taken;
    for (const auto& n : m.allNames()) taken.insert(n);
    auto unique = [&](const std::string& wanted, bool global) {
      std::string chosen = wanted;
      if (global)
        for (int i = 1; taken.count(chosen); ++i) chosen = wanted + "_stereo" + (i > 1 ? std::to_string(i) : "");
      if (chosen != wanted) {
        ctx.diags.warning(ctx.file, "the shader already declares '" + wanted + "'; the injected one is named '" +
                                        chosen + "'");
        report["renamed"][wanted] = chosen;
      }
      taken.insert(chosen);
      return chosen;
    };
    // Block members are scoped by the instance, except HLSL cbuffer members and loose uniforms.
    bool membersGlobal = source == EyeSource::LooseUniforms || source == EyeSource::SpecConstant ||
                         ctx.source.language == SourceLanguage::Hlsl;
    const std::string wantedNames[3] = {o.eyeSignName, o.separationName, o.convergenceName};
    for (int i = 0; i < 3; ++i) ctx.eye.names[i] = unique(wantedNames[i], membersGlobal);

    uint32_t f = m.typeFloat(32);
    switch (source) {
      case EyeSource::LooseUniforms: {
        uint32_t pointer = m.typePointer(spv::StorageClassUniformConstant, f);
        uint32_t nextLocation = firstFreeUniformLocation(m);
        for (int i = 0; i < 3; ++i) {
          uint32_t var = m.addGlobalVariable(pointer, spv::StorageClassUniformConstant);
          m.setName(var, ctx.eye.names[i]);
          m.decorate(var, spv::DecorationLocation, {nextLocation + i});  // for validation; not emitted
          ctx.eye.looseVariables[i] = var;
        }
        report["declared"] = "loose uniforms";
        break;
      }
      case EyeSource::SpecConstant: {
        const float defaults[3] = {0.0f, 0.0f, 1.0f};  // mono until the application specializes
        for (int i = 0; i < 3; ++i) {
          uint32_t id = m.specConstantFloat(defaults[i]);
          m.setName(id, ctx.eye.names[i]);
          m.decorate(id, spv::DecorationSpecId, {o.specIdBase + i});
          ctx.eye.specConstants[i] = id;
        }
        report["declared"] = "specialization constants";
        report["specIds"] = {o.specIdBase, o.specIdBase + 1, o.specIdBase + 2};
        break;
      }
      case EyeSource::PushConstant: {
        if (!mergeIntoPushConstants(ctx, f)) declareBlock(ctx, f, spv::StorageClassPushConstant);
        report["declared"] = "push constants";
        report["offset"] = pushOffset_;
        break;
      }
      default: {
        declareBlock(ctx, f, spv::StorageClassUniform);
        report["declared"] = "uniform block";
        report["block"] = m.name(blockType_);
        report["instance"] = m.name(ctx.eye.variable);
        if (auto set = m.decorationValue(ctx.eye.variable, spv::DecorationDescriptorSet)) report["set"] = *set;
        bool gl = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
        if (auto b = m.decorationValue(ctx.eye.variable, spv::DecorationBinding); b && (!gl || o.glBinding))
          report["binding"] = *b;  // OpenGL blocks without --gl-binding are bound by name
        break;
      }
    }
    report["names"] = {ctx.eye.names[0], ctx.eye.names[1], ctx.eye.names[2]};
    ctx.eyeDeclared = true;
    return PassResult::Changed;
  }

 private:
  uint32_t blockType_ = 0;
  uint32_t pushOffset_ = 0;

  static uint32_t firstFreeUniformLocation(const spirv::Module& m) {
    uint32_t next = 0;
    for (const auto& inst : m.typesValues)
      if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassUniformConstant)
        if (auto loc = m.decorationValue(inst.resultId, spv::DecorationLocation)) next = std::max(next, *loc + 16);
    return next;
  }

  // The binding for the new block: the option, else one past the highest binding in the set. HLSL
  // registers are per class (b, t, s, u), so for HLSL only constant buffers count.
  static uint32_t chooseBinding(const PassContext& ctx, uint32_t set) {
    const auto& o = ctx.options.eye;
    if (ctx.source.language == SourceLanguage::Hlsl && o.hlslRegister) return *o.hlslRegister;
    if (o.binding) return *o.binding;
    auto highest = highestBinding(ctx.module, set, ctx.source.language == SourceLanguage::Hlsl);
    return highest ? *highest + 1 : 0;
  }

  void declareBlock(PassContext& ctx, uint32_t f, spv::StorageClass storage) {
    auto& m = ctx.module;
    const auto& o = ctx.options.eye;
    blockType_ = m.newStruct({f, f, f});
    std::set<std::string> taken;
    for (const auto& n : m.allNames()) taken.insert(n);
    std::string blockName = o.blockName, instanceName = o.instanceName;
    for (int i = 2; taken.count(blockName); ++i) blockName = o.blockName + std::to_string(i);
    for (int i = 2; taken.count(instanceName); ++i) instanceName = o.instanceName + std::to_string(i);
    auto& report = ctx.report["passes"][name()];
    for (const auto& [wanted, chosen] : {std::pair{o.blockName, blockName}, std::pair{o.instanceName, instanceName}})
      if (wanted != chosen) {
        ctx.diags.warning(ctx.file, "the shader already declares '" + wanted + "'; the injected block uses '" +
                                        chosen + "'");
        report["renamed"][wanted] = chosen;
      }
    m.setName(blockType_, blockName);
    m.decorate(blockType_, spv::DecorationBlock);
    for (uint32_t i = 0; i < 3; ++i) {
      m.setMemberName(blockType_, i, ctx.eye.names[i]);
      m.decorateMember(blockType_, i, spv::DecorationOffset, {4 * i});
    }
    uint32_t var = m.addGlobalVariable(m.typePointer(storage, blockType_), storage);
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
  }

  // Appends the three floats to the shader's own push-constant block (one per entry point allowed).
  bool mergeIntoPushConstants(PassContext& ctx, uint32_t f) {
    auto& m = ctx.module;
    for (auto& inst : m.typesValues) {
      if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassPushConstant) continue;
      uint32_t var = inst.resultId;
      uint32_t structType = m.pointeeType(inst.typeId);
      uint32_t offset = (explicitSize(m, structType) + 3) & ~3u;
      // Struct types are not shared between variables in glslang output; extend it in place.
      for (auto& t : m.typesValues)
        if (t.resultId == structType) {
          uint32_t first = static_cast<uint32_t>(t.operands.size());
          t.operands.insert(t.operands.end(), {f, f, f});
          m.invalidateDefinitions();
          for (uint32_t i = 0; i < 3; ++i) {
            m.setMemberName(structType, first + i, ctx.eye.names[i]);
            m.decorateMember(structType, first + i, spv::DecorationOffset, {offset + 4 * i});
          }
          ctx.eye.variable = var;
          ctx.eye.firstMember = first;
          pushOffset_ = offset;
          return true;
        }
    }
    return false;
  }
};

}  // namespace

std::unique_ptr<Pass> createEyeParamsPass() { return std::make_unique<EyeParamsPass>(); }

}  // namespace stereoshift
