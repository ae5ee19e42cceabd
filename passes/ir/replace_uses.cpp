#include "passes/ir/replace_uses.h"

#include "passes/ir/walker.h"

namespace stereoshift::spirv {

size_t replaceAllUses(Module& module, uint32_t from, uint32_t to) {
  size_t replaced = 0;
  forEachFunctionInstruction(module, [&](Instruction& inst, Function&, Block&) {
    for (size_t k = 0; k < inst.operands.size(); ++k)
      if (inst.operands[k] == from && isValueOperand(inst, k)) {
        inst.operands[k] = to;
        ++replaced;
      }
  });
  return replaced;
}

}  // namespace stereoshift::spirv
