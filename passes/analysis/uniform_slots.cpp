// See uniform_slots.h.
#include "passes/analysis/uniform_slots.h"

#include <algorithm>

namespace stereoshift::analysis {

using spirv::Instruction;
using spirv::Module;

bool isGlslExtInst(const Module& m, const Instruction& inst, std::initializer_list<GLSLstd450> which) {
  if (inst.opcode != spv::OpExtInst) return false;
  const Instruction* set = m.definition(inst.operand(0));
  if (!set || set->stringOperand(0) != "GLSL.std.450") return false;
  return std::find(which.begin(), which.end(), GLSLstd450(inst.operand(1))) != which.end();
}

std::optional<uint32_t> constantValue(const Module& m, uint32_t id) {
  const Instruction* def = m.definition(id);
  if (!def || def->opcode != spv::OpConstant) return std::nullopt;
  return def->operand(0);
}

bool isUniformStorage(spv::StorageClass s) {
  return s == spv::StorageClassUniform || s == spv::StorageClassPushConstant || s == spv::StorageClassUniformConstant;
}

std::optional<Slot> slotOfPointer(const Module& m, uint32_t pointer) {
  std::vector<uint32_t> reversed;
  for (int depth = 0; depth < 16; ++depth) {
    const Instruction* def = m.definition(pointer);
    if (!def) return std::nullopt;
    if (def->opcode == spv::OpVariable) {
      if (!isUniformStorage(spv::StorageClass(def->operand(0)))) return std::nullopt;
      return Slot{pointer, std::vector<uint32_t>(reversed.rbegin(), reversed.rend())};
    }
    if (def->opcode != spv::OpAccessChain && def->opcode != spv::OpInBoundsAccessChain) return std::nullopt;
    for (size_t k = def->operands.size(); k-- > 1;) {
      auto value = constantValue(m, def->operands[k]);
      if (!value) return std::nullopt;  // indexed by a variable: not one fixed value
      reversed.push_back(*value);
    }
    pointer = def->operand(0);
  }
  return std::nullopt;
}

// The slot an OpLoad reads, if it reads one.
std::optional<Slot> loadedSlot(const Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (!def || def->opcode != spv::OpLoad) return std::nullopt;
  return slotOfPointer(m, def->operand(0));
}

// Type of the value a slot holds.
uint32_t slotType(const Module& m, const Slot& slot) {
  const Instruction* var = m.definition(slot.variable);
  uint32_t type = m.pointeeType(var->typeId);
  for (uint32_t index : slot.indices) {
    const Instruction* def = m.definition(type);
    if (!def) return 0;
    if (def->opcode == spv::OpTypeStruct) type = def->operand(index);
    else if (def->opcode == spv::OpTypeVector || def->opcode == spv::OpTypeMatrix || def->opcode == spv::OpTypeArray)
      type = def->operand(0);
    else return 0;
  }
  if (slot.inverseTranslation) {
    const Instruction* matrix = m.definition(type);
    return matrix && matrix->opcode == spv::OpTypeMatrix ? matrix->operand(0) : 0;
  }
  return type;
}

// "instance.member" (block type name when the instance is unnamed, as in HLSL cbuffers), or the
// loose uniform's name. Array and vector indices are written as [i].
std::string slotName(const Module& m, const Slot& slot) {
  const Instruction* var = m.definition(slot.variable);
  std::string text = m.name(slot.variable);
  uint32_t type = m.pointeeType(var->typeId);
  if (text.empty()) text = m.name(type);
  for (uint32_t index : slot.indices) {
    const Instruction* def = m.definition(type);
    if (def && def->opcode == spv::OpTypeStruct) {
      std::string member = m.memberName(type, index);
      text += (text.empty() ? "" : ".") + (member.empty() ? std::to_string(index) : member);
      type = def->operand(index);
    } else {
      text += "[" + std::to_string(index) + "]";
      type = def ? def->operand(0) : 0;
    }
  }
  return slot.inverseTranslation ? "inverse(" + text + ")[3]" : text;
}

std::optional<std::string> slotSourceAccess(const Module& m, const Slot& slot) {
  if (slot.inverseTranslation) return std::nullopt;
  const Instruction* var = m.definition(slot.variable);
  if (!var) return std::nullopt;
  std::string text = m.name(slot.variable);
  uint32_t type = m.pointeeType(var->typeId);
  for (uint32_t index : slot.indices) {
    const Instruction* def = m.definition(type);
    if (!def || def->opcode != spv::OpTypeStruct) return std::nullopt;
    std::string member = m.memberName(type, index);
    if (member.empty()) return std::nullopt;
    text += (text.empty() ? "" : ".") + member;
    type = def->operand(index);
  }
  bool madeUp = text.empty() || text.starts_with("gl_") || text.find("stereoshift_") != std::string::npos;
  if (madeUp) return std::nullopt;
  return text;
}

// The innermost name of a slot: the member name, or the loose uniform's name.
std::string slotLeafName(const Module& m, const Slot& slot) {
  Slot plain = slot;
  plain.inverseTranslation = false;
  std::string full = slotName(m, plain);
  size_t dot = full.find_last_of('.');
  return dot == std::string::npos ? full : full.substr(dot + 1);
}

bool slotMatchesName(const Module& m, const Slot& slot, const std::string& wanted) {
  if (wanted.empty()) return false;
  if (slotName(m, slot) == wanted || slotLeafName(m, slot) == wanted) return true;
  // "Block.member" where the module names the instance.
  if (!slot.indices.empty()) {
    uint32_t type = m.pointeeType(m.definition(slot.variable)->typeId);
    return m.name(type) + "." + m.memberName(type, slot.indices.front()) == wanted;
  }
  return false;
}

// The slot a value reads: a load of it, a member of a whole-struct load (`Camera c = camera;
// c.position`), or the translation column of the inverse of a loaded matrix (`inverse(view)[3]`).
std::optional<Slot> valueSlot(const Module& m, uint32_t value) {
  if (auto slot = loadedSlot(m, value)) return slot;
  const Instruction* def = m.definition(value);
  if (!def || def->opcode != spv::OpCompositeExtract) return std::nullopt;
  std::vector<uint32_t> path(def->operands.begin() + 1, def->operands.end());
  const Instruction* from = m.definition(def->operand(0));
  if (from && isGlslExtInst(m, *from, {GLSLstd450MatrixInverse}) && path == std::vector<uint32_t>{3}) {
    auto matrix = loadedSlot(m, from->operand(2));
    if (!matrix || !isMat4(m, slotType(m, *matrix))) return std::nullopt;
    matrix->inverseTranslation = true;
    return matrix;
  }
  auto whole = loadedSlot(m, def->operand(0));
  if (!whole) return std::nullopt;
  const Instruction* type = m.definition(slotType(m, *whole));
  if (!type || type->opcode != spv::OpTypeStruct) return std::nullopt;  // a vector's component: not a position
  whole->indices.insert(whole->indices.end(), path.begin(), path.end());
  return whole;
}

std::optional<Slot> cameraSide(const Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (def && def->opcode == spv::OpVectorShuffle && def->operands.size() == 5 && def->operand(0) == def->operand(1) &&
      def->operand(2) == 0 && def->operand(3) == 1 && def->operand(4) == 2)
    value = def->operand(0);  // camera.xyz
  auto slot = valueSlot(m, value);
  if (!slot) return std::nullopt;
  const Instruction* type = m.definition(slotType(m, *slot));
  if (!type || type->opcode != spv::OpTypeVector || (type->operand(1) != 3 && type->operand(1) != 4)) return std::nullopt;
  const Instruction* component = m.definition(type->operand(0));
  if (!component || component->opcode != spv::OpTypeFloat) return std::nullopt;
  return slot;
}

bool isMat4(const Module& m, uint32_t type) {
  const Instruction* def = m.definition(type);
  if (!def || def->opcode != spv::OpTypeMatrix || def->operand(1) != 4) return false;
  const Instruction* column = m.definition(def->operand(0));
  return column && column->opcode == spv::OpTypeVector && column->operand(1) == 4;
}

}  // namespace stereoshift::analysis
