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

namespace {

// The component count of a 32-bit float scalar or vector type with fewer than 4 (0 otherwise), and
// its component type.
uint32_t narrowFloatCount(const spirv::Module& m, uint32_t type, uint32_t* component) {
  const spirv::Instruction* def = m.definition(type);
  if (def && def->opcode == spv::OpTypeFloat && def->operand(0) == 32) {
    *component = type;
    return 1;
  }
  if (!def || def->opcode != spv::OpTypeVector || def->operand(1) >= 4) return 0;
  const spirv::Instruction* element = m.definition(def->operand(0));
  if (!element || element->opcode != spv::OpTypeFloat || element->operand(0) != 32) return 0;
  *component = def->operand(0);
  return def->operand(1);
}

// Whether every use of `var` in the functions is a whole load or store or an access chain into it.
bool onlyLoadedStoredOrIndexed(const spirv::Module& m, uint32_t var) {
  for (const auto& function : m.functions)
    for (const auto& block : function.blocks)
      for (const auto& inst : block.instructions)
        for (size_t i = 0; i < inst.operands.size(); ++i) {
          if (inst.operands[i] != var) continue;
          bool allowed = i == 0 && (inst.opcode == spv::OpLoad || inst.opcode == spv::OpStore ||
                                    inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain);
          if (!allowed) return false;
        }
  return true;
}

}  // namespace

void widenLegacyFragmentOutputs(spirv::Module& m) {
  if (m.executionModel() != spv::ExecutionModelFragment) return;
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> widened;  // variable -> (component count, float type)
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassOutput ||
        m.hasDecoration(inst.resultId, spv::DecorationBuiltIn))
      continue;
    uint32_t component = 0;
    uint32_t count = narrowFloatCount(m, m.pointeeType(inst.typeId), &component);
    if (count && onlyLoadedStoredOrIndexed(m, inst.resultId)) widened[inst.resultId] = {count, component};
  }
  if (widened.empty()) return;
  const uint32_t floatType = widened.begin()->second.second;
  const uint32_t vec4 = m.typeVector(floatType, 4);
  const uint32_t vec4Pointer = m.typePointer(spv::StorageClassOutput, vec4);
  const uint32_t zero = m.constantFloat(0.0f), one = m.constantFloat(1.0f);
  std::vector<spirv::Instruction> moved;  // after the types and constants they now use
  std::erase_if(m.typesValues, [&](const spirv::Instruction& inst) {
    if (inst.opcode != spv::OpVariable || !widened.count(inst.resultId)) return false;
    moved.push_back(inst);
    moved.back().typeId = vec4Pointer;
    return true;
  });
  m.typesValues.insert(m.typesValues.end(), moved.begin(), moved.end());
  for (auto& function : m.functions)
    for (auto& block : function.blocks)
      for (size_t k = 0; k < block.instructions.size(); ++k) {
        spirv::Instruction& inst = block.instructions[k];
        auto it = widened.find(inst.operand(0));
        if (it == widened.end() || (inst.opcode != spv::OpStore && inst.opcode != spv::OpLoad)) continue;
        const uint32_t count = it->second.first;
        const auto at = block.instructions.begin() + static_cast<std::ptrdiff_t>(k);
        if (inst.opcode == spv::OpStore) {
          // (v, 0, ..., 1): what the shader wrote, then the components it did not.
          spirv::Instruction pad(spv::OpCompositeConstruct, vec4, m.takeId(), {inst.operand(1)});
          for (uint32_t c = count; c < 3; ++c) pad.operands.push_back(zero);
          pad.operands.push_back(one);
          inst.operands[1] = pad.resultId;
          block.instructions.insert(at, pad);
        } else {
          const uint32_t narrowType = inst.typeId, value = inst.resultId, wide = m.takeId();
          inst.typeId = vec4;
          inst.resultId = wide;
          spirv::Instruction back = count == 1 ? spirv::Instruction(spv::OpCompositeExtract, narrowType, value, {wide, 0})
                                               : spirv::Instruction(spv::OpVectorShuffle, narrowType, value, {wide, wide});
          for (uint32_t c = 0; count > 1 && c < count; ++c) back.operands.push_back(c);
          block.instructions.insert(at + 1, back);
        }
        ++k;
      }
  m.invalidateDefinitions();
}

}  // namespace stereoshift
