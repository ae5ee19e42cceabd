// See clip_positions.h: the one place that says which outputs are the clip position, which pointers
// address them and which values equal the application's mono position.
#include "passes/analysis/clip_positions.h"

#include <algorithm>
#include <map>

namespace stereoshift {

using spirv::Instruction;

namespace {

std::vector<ClipPosition> findOutputs(const spirv::Module& m) {
  std::vector<ClipPosition> positions;
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->opcode != spv::OpVariable || var->operand(0) != spv::StorageClassOutput) continue;
    uint32_t type = m.pointeeType(var->typeId);
    bool arrayed = false;
    const Instruction* typeDef = m.definition(type);
    if (typeDef && typeDef->opcode == spv::OpTypeArray) {
      arrayed = true;
      type = typeDef->operand(0);
      typeDef = m.definition(type);
    }
    std::string varName = m.name(id);
    if (m.decorationValue(id, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInPosition)) {
      positions.push_back({id, false, 0, arrayed, varName.empty() ? "position" : varName});
      continue;
    }
    if (!typeDef || typeDef->opcode != spv::OpTypeStruct) continue;
    for (uint32_t member = 0; member < typeDef->operands.size(); ++member)
      if (m.memberDecorationValue(type, member, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInPosition))
        positions.push_back({id, true, member, arrayed, m.name(type) + "." + m.memberName(type, member)});
  }
  return positions;
}

enum class Reach { None, Whole, Component };

// How far an access chain reaches into `position`: to the whole vec4, into one of its components,
// or not into it at all (another member of its block, or not a chain on its variable).
Reach chainReach(const spirv::Module& m, const Instruction& inst, const ClipPosition& position) {
  if (inst.opcode != spv::OpAccessChain && inst.opcode != spv::OpInBoundsAccessChain) return Reach::None;
  if (inst.operand(0) != position.variable) return Reach::None;
  size_t indices = inst.operands.size() - 1;
  if (!position.isMember) return indices == 0 ? Reach::Whole : Reach::Component;
  const Instruction* index = m.definition(inst.operand(1));
  if (indices == 0 || !index || index->opcode != spv::OpConstant || index->operand(0) != position.member)
    return Reach::None;
  return indices == 1 ? Reach::Whole : Reach::Component;
}

}  // namespace

ClipPositionAnalysis::ClipPositionAnalysis(const spirv::Module& m) : outputs_(findOutputs(m)) {
  whole_.resize(outputs_.size());
  components_.resize(outputs_.size());
  for (size_t i = 0; i < outputs_.size(); ++i)
    if (!outputs_[i].isMember) whole_[i].insert(outputs_[i].variable);
  for (const auto& fn : m.functions)
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions)
        for (size_t i = 0; i < outputs_.size(); ++i) {
          Reach reach = chainReach(m, inst, outputs_[i]);
          if (reach == Reach::Whole) whole_[i].insert(inst.resultId);
          if (reach == Reach::Component) components_[i].insert(inst.resultId);
        }
  for (const auto& pointers : whole_) allWhole_.insert(pointers.begin(), pointers.end());
  if (outputs_.empty()) return;

  // The mono values: stores to the position and loads of it, then local copies to a fixpoint
  // (a local whose every store is a mono value holds the position; its loads are mono values too).
  std::map<uint32_t, std::vector<uint32_t>> storesTo;
  std::set<uint32_t> locals;
  for (const auto& fn : m.functions)
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions) {
        if (inst.opcode == spv::OpVariable) locals.insert(inst.resultId);
        if (inst.opcode != spv::OpStore) continue;
        storesTo[inst.operand(0)].push_back(inst.operand(1));
        if (allWhole_.count(inst.operand(0))) monoValues_.insert(inst.operand(1));
      }
  auto holdsPosition = [&](uint32_t pointer) {
    if (allWhole_.count(pointer)) return true;
    if (!locals.count(pointer)) return false;
    auto stores = storesTo.find(pointer);
    return stores != storesTo.end() && !stores->second.empty() &&
           std::all_of(stores->second.begin(), stores->second.end(),
                       [&](uint32_t value) { return monoValues_.count(value) > 0; });
  };
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& fn : m.functions)
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions)
          if (inst.opcode == spv::OpLoad && !monoValues_.count(inst.resultId) && holdsPosition(inst.operand(0))) {
            monoValues_.insert(inst.resultId);
            grew = true;
          }
  }
}

}  // namespace stereoshift
