// Def-use lists of a module: the instruction that defines every id, and every place a function
// body uses an id as a value, as (instruction, operand word). SPIRV-Tools' DefUseManager plays the
// same role in its optimizer; this one is built on demand by whoever asks and never kept up to date
// by the module.
//
// When it must be rebuilt: it points into the module's instruction vectors, so any insertion or
// removal of an instruction (which may move them), and any edit of a result id or of an operand,
// makes it stale. Build it, ask, edit, and build a new one before asking again. An analysis that
// only reads the module (the folded copy, a pass's detection phase) builds it once.
//
// What counts as a use: an operand word of a function-body instruction that isValueOperand()
// reports as an id: values, pointers, functions called, ext-inst sets, and (as isValueOperand
// allows) the labels of OpPhi. Not uses: result types, literal operands (extract indices, shuffle
// components, operand masks), and the references of global instructions (decorations, names,
// entry-point interfaces, type and constant operands), which name an id rather than read its value.
#pragma once

#include "passes/ir/module.h"

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace stereoshift::spirv {

struct Use {
  const Instruction* user = nullptr;
  size_t operand = 0;  // index into user->operands
  const Function* function = nullptr;
  const Block* block = nullptr;
};

class DefUse {
 public:
  explicit DefUse(const Module& module);

  // The instruction that defines `id` (any section, function definitions and parameters
  // included); null for labels, which the IR keeps as Block::labelId, and for unknown ids.
  const Instruction* definition(uint32_t id) const;
  // The function whose body or parameter list defines `id`; null for global ids.
  const Function* definingFunction(uint32_t id) const;
  // Every use of `id`, in encoding order (instructions in module order, operands in word order).
  const std::vector<Use>& uses(uint32_t id) const;
  // The distinct instructions that use `id`, in encoding order.
  std::vector<const Instruction*> users(uint32_t id) const;

 private:
  struct Definition {
    const Instruction* instruction = nullptr;
    const Function* function = nullptr;
  };
  std::unordered_map<uint32_t, Definition> definitions_;
  std::unordered_map<uint32_t, std::vector<Use>> uses_;
};

}  // namespace stereoshift::spirv
