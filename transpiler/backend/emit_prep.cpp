#include "transpiler/backend/emit_prep.h"

#include <algorithm>

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

}  // namespace stereoshift
