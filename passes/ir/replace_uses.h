// Replace-all-uses: makes every value use of one id read another, as a pass does when it computes
// a corrected value and wants the rest of the shader to see it instead of the original.
#pragma once

#include "passes/ir/module.h"

#include <cstddef>
#include <cstdint>

namespace stereoshift::spirv {

// Rewrites every function-body operand word that isValueOperand() reports as an id and that holds
// `from` into `to` (the uses DefUse lists). Literal operands that happen to equal `from` (extract
// indices, shuffle components, masks), result ids, result types and global references
// (decorations, names, interfaces) are left alone. Returns how many operands changed. Definitions
// do not move, so Module::definition() stays valid; a DefUse built before is stale afterwards.
size_t replaceAllUses(Module& module, uint32_t from, uint32_t to);

}  // namespace stereoshift::spirv
