// Instruction walkers: visit the instructions of a module, or only those of its function bodies,
// in the order they are encoded, with the enclosing function and block at hand. They replace the
// nested `for (fn : functions) for (block : fn.blocks) for (inst : block.instructions)` loops.
//
// The walkers hold references into the section vectors while they run: a visitor may edit the
// instruction it is given (operands, ids) but must not insert or erase instructions (that moves
// the vectors under the walk); collect what to insert and do it after the walk.
#pragma once

#include "passes/ir/module.h"

#include <type_traits>

namespace stereoshift::spirv {

namespace walker_detail {
template <class M, class T>
using Constness = std::conditional_t<std::is_const_v<M>, const T, T>;
}  // namespace walker_detail

// Calls visit(inst, function, block) for every instruction inside a block of every function
// (OpPhi .. terminator; the implied OpLabel is not an instruction of the IR), functions in module
// order, blocks in layout order. `ModuleT` is Module or const Module; the references are const
// for a const module.
template <class ModuleT, class Visit>
void forEachFunctionInstruction(ModuleT& module, Visit&& visit) {
  for (auto& fn : module.functions)
    for (auto& block : fn.blocks)
      for (auto& inst : block.instructions) visit(inst, fn, block);
}

// Whether pred(inst, function, block) holds for some function-body instruction; stops at the first.
template <class ModuleT, class Pred>
bool anyFunctionInstruction(ModuleT& module, Pred&& pred) {
  for (auto& fn : module.functions)
    for (auto& block : fn.blocks)
      for (auto& inst : block.instructions)
        if (pred(inst, fn, block)) return true;
  return false;
}

// How many stores in the module's function bodies write (any part of) `variable`.
inline int storesTo(const Module& module, uint32_t variable) {
  int stores = 0;
  forEachFunctionInstruction(module, [&](const Instruction& inst, const Function&, const Block&) {
    if (inst.opcode == spv::OpStore && module.rootVariable(inst.operand(0)) == variable) ++stores;
  });
  return stores;
}

// Calls visit(inst, function, block) for every instruction of the module in encoding order: the
// global sections (function and block are null), then each function's OpFunction (block null),
// its parameters (block null) and its block instructions. OpLabel and OpFunctionEnd are implied
// by the IR and not visited.
template <class ModuleT, class Visit>
void forEachInstruction(ModuleT& module, Visit&& visit) {
  using FunctionT = walker_detail::Constness<ModuleT, Function>;
  using BlockT = walker_detail::Constness<ModuleT, Block>;
  for (auto* section : {&module.capabilities, &module.extensions, &module.extInstImports, &module.memoryModel,
                        &module.entryPoints, &module.executionModes, &module.debugSource, &module.debugNames,
                        &module.debugModuleProcessed, &module.annotations, &module.typesValues})
    for (auto& inst : *section) visit(inst, static_cast<FunctionT*>(nullptr), static_cast<BlockT*>(nullptr));
  for (auto& fn : module.functions) {
    visit(fn.definition, &fn, static_cast<BlockT*>(nullptr));
    for (auto& parameter : fn.parameters) visit(parameter, &fn, static_cast<BlockT*>(nullptr));
    for (auto& block : fn.blocks)
      for (auto& inst : block.instructions) visit(inst, &fn, &block);
  }
}

}  // namespace stereoshift::spirv
