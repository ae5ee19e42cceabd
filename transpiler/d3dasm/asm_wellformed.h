// What D3D's assembler would refuse in a dump, checked before the assembly route edits it: this
// turns an assembly text into its first such error, located, or none. 3Dmigoto assembles the
// edited text when the game loads the shader; a dump it cannot assemble is lost in the game, so
// the tool refuses it here with the line and column instead of writing a file that fails there.
//   - an instruction whose opcode is no shader model 4 or 5 instruction (after the modifiers the
//     disassembler writes: `_sat`, bracketed parts, `_indexable`, `_aoffimmi`, `_uint`, the
//     conditional `_z` / `_nz`);
//   - a constant buffer read (`cb3[2].x`) that no `dcl_constantbuffer cb3[...]` declares.
#pragma once

#include "transpiler/d3dasm/asm_text.h"

#include <optional>

namespace stereoshift::d3dasm {

std::optional<AsmError> findAssemblerError(const AsmText& text);

}  // namespace stereoshift::d3dasm
