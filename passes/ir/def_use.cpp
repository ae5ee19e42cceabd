#include "passes/ir/def_use.h"

#include "passes/ir/walker.h"

namespace stereoshift::spirv {

DefUse::DefUse(const Module& module) {
  forEachInstruction(module, [&](const Instruction& inst, const Function* fn, const Block* block) {
    if (inst.resultId) definitions_[inst.resultId] = {&inst, fn};
    if (!block) return;  // global instructions and function headers name ids; they do not use values
    for (size_t k = 0; k < inst.operands.size(); ++k)
      if (isValueOperand(inst, k)) uses_[inst.operands[k]].push_back({&inst, k, fn, block});
  });
}

const Instruction* DefUse::definition(uint32_t id) const {
  auto it = definitions_.find(id);
  return it == definitions_.end() ? nullptr : it->second.instruction;
}

const Function* DefUse::definingFunction(uint32_t id) const {
  auto it = definitions_.find(id);
  return it == definitions_.end() ? nullptr : it->second.function;
}

const std::vector<Use>& DefUse::uses(uint32_t id) const {
  static const std::vector<Use> kNone;
  auto it = uses_.find(id);
  return it == uses_.end() ? kNone : it->second;
}

std::vector<const Instruction*> DefUse::users(uint32_t id) const {
  std::vector<const Instruction*> out;
  for (const Use& use : uses(id))
    if (out.empty() || out.back() != use.user) out.push_back(use.user);
  return out;
}

}  // namespace stereoshift::spirv
