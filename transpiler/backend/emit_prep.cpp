#include "transpiler/backend/emit_prep.h"

#include <algorithm>
#include <map>
#include <set>

namespace stereoshift {

// OpenGL shaders that relied on glBindAttribLocation, glGetUniformLocation and glUniform1i must not
// gain layout(location/binding) qualifiers they did not have: drop what glslang auto-assigned.
void stripAutoAssignedQualifiers(spirv::Module& m, const SourceInfo& info) {
  if (info.language != SourceLanguage::Glsl || info.vulkan) return;
  auto keyOf = [&](uint32_t var) {
    std::vector<std::string> keys = {m.name(var)};
    if (const auto* def = m.definition(var)) keys.push_back(m.name(m.pointeeType(def->typeId)));
    return keys;
  };
  auto explicitIn = [&](const std::set<std::string>& set, uint32_t var) {
    for (const auto& k : keyOf(var))
      if (!k.empty() && set.count(k)) return true;
    return false;
  };
  for (const auto& inst : std::vector<spirv::Instruction>(m.typesValues)) {
    if (inst.opcode != spv::OpVariable) continue;
    uint32_t var = inst.resultId;
    if (!explicitIn(info.explicitLocation, var)) m.removeDecorations(var, spv::DecorationLocation);
    if (!explicitIn(info.explicitBinding, var)) m.removeDecorations(var, spv::DecorationBinding);
    m.removeDecorations(var, spv::DecorationDescriptorSet);
  }
}

EmitHints collectHints(const spirv::Module& m) {
  EmitHints hints;
  for (const auto& inst : m.annotations) {
    if (inst.opcode != spv::OpDecorateString || inst.operand(1) != uint32_t(spv::DecorationUserSemantic)) continue;
    uint32_t var = inst.operand(0);
    auto location = m.decorationValue(var, spv::DecorationLocation);
    auto storage = m.storageClassOf(var);
    if (!location || !storage) continue;
    std::string semantic = inst.stringOperand(2);
    std::transform(semantic.begin(), semantic.end(), semantic.begin(), ::toupper);
    if (*storage == spv::StorageClassInput) hints.inputSemantics[*location] = semantic;
    if (*storage == spv::StorageClassOutput) hints.outputSemantics[*location] = semantic;
  }
  // SPIRV-Cross names HLSL cbuffer members "<instance>_<member>" (instance "_<id>" when unnamed).
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassUniform) continue;
    uint32_t type = m.pointeeType(inst.typeId);
    const auto* def = m.definition(type);
    if (!def || def->opcode != spv::OpTypeStruct) continue;
    std::string instance = m.name(inst.resultId);
    if (instance.empty()) instance = "_" + std::to_string(inst.resultId);
    for (uint32_t i = 0; i < def->operands.size(); ++i) {
      std::string member = m.memberName(type, i);
      if (!member.empty()) hints.cbufferMemberNames[instance + "_" + member] = member;
    }
  }
  return hints;
}

void signIntegerBuiltIns(spirv::Module& m) {
  uint32_t uintType = 0;
  std::set<uint32_t> retyped;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassInput ||
        m.decorationValue(inst.resultId, spv::DecorationBuiltIn) != uint32_t(spv::BuiltInInvocationId))
      continue;
    const spirv::Instruction* type = m.definition(m.pointeeType(inst.typeId));
    if (!type || type->opcode != spv::OpTypeInt || type->operand(0) != 32 || type->operand(1) != 0) continue;
    uintType = type->resultId;
    retyped.insert(inst.resultId);
  }
  if (retyped.empty()) return;
  const uint32_t intType = m.typeInt(32, true);
  const uint32_t intPointer = m.typePointer(spv::StorageClassInput, intType);
  std::map<uint32_t, uint32_t> signedOf;  // each load's uint value -> the int it converts
  // The variables move after the types they now use (a new int type is appended last).
  std::vector<spirv::Instruction> moved;
  std::erase_if(m.typesValues, [&](const spirv::Instruction& inst) {
    if (inst.opcode != spv::OpVariable || !retyped.count(inst.resultId)) return false;
    moved.push_back(inst);
    moved.back().typeId = intPointer;
    return true;
  });
  m.typesValues.insert(m.typesValues.end(), moved.begin(), moved.end());
  for (auto& function : m.functions)
    for (auto& block : function.blocks)
      for (size_t k = 0; k < block.instructions.size(); ++k) {
        spirv::Instruction& load = block.instructions[k];
        if (load.opcode != spv::OpLoad || !retyped.count(load.operand(0))) continue;
        const uint32_t value = load.resultId, signedValue = m.takeId();
        load.typeId = intType;
        load.resultId = signedValue;
        spirv::Instruction cast;
        cast.opcode = spv::OpBitcast;
        cast.typeId = uintType;
        cast.resultId = value;
        cast.operands = {signedValue};
        block.instructions.insert(block.instructions.begin() + static_cast<std::ptrdiff_t>(k) + 1, cast);
        signedOf[value] = signedValue;
      }
  // An index takes the int itself: a tessellation control shader's per-vertex outputs must be indexed
  // with gl_InvocationID as it is, not a conversion of it.
  for (auto& function : m.functions)
    for (auto& block : function.blocks)
      for (auto& inst : block.instructions)
        if (inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain)
          for (size_t i = 1; i < inst.operands.size(); ++i)
            if (auto it = signedOf.find(inst.operands[i]); it != signedOf.end()) inst.operands[i] = it->second;
  m.invalidateDefinitions();
}

}  // namespace stereoshift
