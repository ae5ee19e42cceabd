// Text form of SPIR-V through SPIRV-Tools: the disassembly that --emit spirv-asm, the pass
// manager's --print-after and the tests print, and the assembler the unit tests build modules with.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift::spirv {

// The disassembly of a module's words (friendly names, indented, no header comment).
std::string disassemble(const std::vector<uint32_t>& words);

// Assembles SPIR-V text, keeping the numeric ids it names; returns empty and sets *error
// ("line:col: error: message" lines) on failure.
std::vector<uint32_t> assemble(const std::string& text, std::string* error);

}  // namespace stereoshift::spirv
