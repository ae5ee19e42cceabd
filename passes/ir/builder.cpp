// See builder.h.
#include "passes/ir/builder.h"

namespace stereoshift::spirv {

size_t splitBlock(Module& module, Function& fn, size_t index, size_t at, uint32_t restLabel) {
  Block& head = fn.blocks[index];
  const uint32_t headLabel = head.labelId;
  Block rest{restLabel, {}};
  rest.instructions.assign(head.instructions.begin() + static_cast<long>(at), head.instructions.end());
  head.instructions.resize(at);
  for (auto& block : fn.blocks)
    for (auto& inst : block.instructions) {
      if (inst.opcode != spv::OpPhi) continue;
      for (size_t k = 1; k < inst.operands.size(); k += 2)
        if (inst.operands[k] == headLabel) inst.operands[k] = restLabel;
    }
  fn.blocks.insert(fn.blocks.begin() + static_cast<long>(index) + 1, std::move(rest));
  module.invalidateDefinitions();
  return index + 1;
}

}  // namespace stereoshift::spirv
