// The instruction builder: this turns "an opcode, a result type and operands" into an instruction
// appended at a cursor (an instruction list a pass is writing: a block's new instructions, or code
// it will splice in), with a result id taken from the module. Passes write SPIR-V through it, as
// Mesa's nir_builder and SPIRV-Tools' InstructionBuilder are used, instead of building Instruction
// objects and taking ids by hand. Ids are taken in the order of the calls, so code written through
// the builder numbers its values as the same code written by hand did. When the cursor is inside
// the module (a block's list), the module's definition index is marked stale on each addition.
#pragma once

#include "passes/ir/module.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace stereoshift::spirv {

class Builder {
 public:
  // Appends to `code`: a list the caller splices into the module later (then it invalidates the
  // definitions once), or a block's own list (`inModule`: each addition invalidates them).
  Builder(Module& module, std::vector<Instruction>& code, bool inModule = false)
      : module_(module), code_(&code), inModule_(inModule) {}

  Module& module() const { return module_; }
  // Moves the cursor to the end of another list (a new block's instructions, say).
  void appendTo(std::vector<Instruction>& code, bool inModule = false) {
    code_ = &code;
    inModule_ = inModule;
  }

  // An id for a value added later with `addAs` (taken now, so it numbers before what the operands
  // of that instruction may still create: a type, a constant).
  uint32_t reserveId() { return module_.takeId(); }

  // Appends `opcode` with a new result id and returns it.
  uint32_t add(spv::Op opcode, uint32_t type, std::vector<uint32_t> operands) {
    uint32_t id = module_.takeId();
    push(Instruction(opcode, type, id, std::move(operands)));
    return id;
  }
  // Appends `opcode` with the result id `id` (one reserveId gave); returns it.
  uint32_t addAs(uint32_t id, spv::Op opcode, uint32_t type, std::vector<uint32_t> operands) {
    push(Instruction(opcode, type, id, std::move(operands)));
    return id;
  }
  // Appends an instruction without result type or id (OpStore, branches, merges).
  void addVoid(spv::Op opcode, std::vector<uint32_t> operands) {
    push(Instruction(opcode, 0, 0, std::move(operands)));
  }

  // The common ones.
  uint32_t load(uint32_t type, uint32_t pointer) { return add(spv::OpLoad, type, {pointer}); }
  void store(uint32_t pointer, uint32_t value) { addVoid(spv::OpStore, {pointer, value}); }
  uint32_t extract(uint32_t type, uint32_t composite, uint32_t index) {
    return add(spv::OpCompositeExtract, type, {composite, index});
  }
  void branch(uint32_t label) { addVoid(spv::OpBranch, {label}); }

 private:
  void push(Instruction instruction) {
    code_->push_back(std::move(instruction));
    if (inModule_) module_.invalidateDefinitions();
  }

  Module& module_;
  std::vector<Instruction>* code_;
  bool inModule_;
};

// Splits block `index` of `fn` before its instruction `at`: the instructions from `at` on move to a
// new block labelled `restLabel` right after it, and every phi that named the block as its
// predecessor names the new block (the split block's successors are now the new block's). Returns
// the new block's index. The definitions are marked stale.
size_t splitBlock(Module& module, Function& fn, size_t index, size_t at, uint32_t restLabel);

}  // namespace stereoshift::spirv
