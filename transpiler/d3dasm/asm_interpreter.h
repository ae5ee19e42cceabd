// An interpreter of SM4/SM5 vertex- and pixel-shader assembly, for checking what the assembly route wrote
// where no GPU runs D3D bytecode: this turns the text of a vertex shader into a program that runs
// on given input registers, constant buffers and textures and yields its output registers, so the
// original and the converted shader can be run on the same inputs (asm_verify.h).
//
// What it runs: the ALU set of SM4/SM5 vertex shaders (float, integer and bit instructions,
// comparisons, conversions, movc, the `_sat` modifier and the source modifiers `-` and `|x|`,
// typed by the instruction as D3D types them), structured control flow (if/else/endif,
// loop/endloop, break/continue and their conditional forms, ret/retc), constant buffers with
// relative indexing, the immediate constant buffer, indexable temporaries, and resource reads
// (ld, sample_l, ...) answered by a callback. What it refuses, with the line: subroutines
// (label/call), switch, and any instruction it does not know; other stages' registers.
// Registers hold 32-bit patterns; float results are rounded to float as the GPU rounds them;
// denormals are kept (the GPU may flush them: both shaders run the same way here). `mad` and the
// dot products are computed unfused (each product and sum rounded to float on its own), which is
// one of the roundings D3D allows; a GPU that fuses them differs from both runs alike.
// Temporaries start at zero, an input component the declaration leaves out reads as the input
// assembler's default (0, 0, 0, 1), and a constant-buffer read out of its rows reads zero. A source
// swizzle of two or three letters in increasing order (`r1.xz`) is a component mask, each letter
// in its own place, as the bytecode's mask mode reads it.
#pragma once

#include "transpiler/d3dasm/asm_text.h"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift::d3dasm {

using Vec4 = std::array<uint32_t, 4>;  // a register's four 32-bit components

struct Machine {
  std::map<uint32_t, Vec4> inputs;                  // v registers
  std::map<uint32_t, std::vector<Vec4>> cbuffers;   // cb slot -> rows
  // A resource read: slot (t<N>), the coordinate operand's value, the opcode ("ld", "sample_l").
  std::function<Vec4(uint32_t slot, const Vec4& coordinate, const std::string& opcode)> resource;
  uint64_t instructionLimit = 1u << 20;             // a loop that does not end stops here
  // Results of a run.
  std::map<uint32_t, Vec4> outputs;                 // o registers written
};

struct RunResult {
  bool ok = false;
  bool limitReached = false;
  std::string error;
  size_t line = 0;
};

struct InputDeclaration {
  uint32_t index = 0;
  uint32_t mask = 0;        // bits 0..3: x..w
  std::string systemValue;  // "vertex_id", "instance_id", "" for plain inputs
};

// What a program is decoded for: to run it (every instruction must be one the interpreter runs), or
// to analyse it (asm_unprojection.h: an instruction it does not run is kept as an opaque one that
// writes its destination, and the program is never run).
enum class DecodeFor { Running, Analysis };

class Program {
 public:
  // Each instruction line decoded once (asm_interpreter_ops.h); null, with the line, the column
  // and why in *error, when the text holds what the interpreter does not run.
  static std::unique_ptr<Program> decode(const AsmText& text, AsmError* error, DecodeFor purpose = DecodeFor::Running);
  ~Program();
  RunResult run(Machine& machine) const;

  const std::vector<InputDeclaration>& inputs() const;
  const std::map<uint32_t, uint32_t>& cbufferSizes() const;  // slot -> rows declared
  const std::map<uint32_t, uint32_t>& outputMasks() const;   // o register -> mask declared
  std::optional<uint32_t> positionOutput() const;            // dcl_output_siv oN, position
  struct Impl;
  const Impl& decoded() const { return *impl_; }             // for the analyses (asm_interpreter_ops.h)

 private:
  explicit Program(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace stereoshift::d3dasm
