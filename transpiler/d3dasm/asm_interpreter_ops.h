// The decoded form the interpreter runs (asm_interpreter.h), shared by its two halves: this turns
// an instruction line into an Op (opcode, destinations with their masks, sources with their
// swizzles and modifiers) once, in asm_interpreter.cpp, so that asm_interpreter_run.cpp only moves
// bits. Private to the interpreter and the analyses that read the decoded program
// (asm_unprojection.h).
#pragma once

#include "transpiler/d3dasm/asm_interpreter.h"

#include <optional>

namespace stereoshift::d3dasm {

enum class File : uint8_t { Null, Temp, Input, Output, IndexableTemp, ConstantBuffer, ImmediateCB, Literal, Resource, Sampler };

enum class Code : uint8_t {
  Mov, Movc, Add, Mul, Mad, Dp2, Dp3, Dp4, Div, Min, Max, Rcp, Rsq, Sqrt, Exp, Log, Frc,
  RoundNe, RoundNi, RoundPi, RoundZ, Sincos, Lt, Ge, Eq, Ne,
  Ilt, Ige, Ieq, Ine, Ult, Uge, Iadd, Imul, Umul, Imad, Umad, Udiv, Ishl, Ishr, Ushr,
  And, Or, Xor, Not, Ineg, Imin, Imax, Umin, Umax, Itof, Utof, Ftoi, Ftou, Bfi, Ubfe, Ibfe, Swapc,
  Countbits, Bfrev,
  IfNz, IfZ, Else, Endif, Loop, Endloop, Break, BreakcNz, BreakcZ, Continue, ContinuecNz, ContinuecZ,
  Ret, RetcNz, RetcZ, Nop, Resource,
  // Decoded for analysis only (Program::decode's DecodeFor::Analysis): an instruction the
  // interpreter does not run, kept with the registers it writes and reads, its result unknown.
  Opaque,
};

// `[4]`, `[r0.x + 4]`: a register's element, fixed or read from a temporary.
struct Index {
  bool relative = false;
  uint32_t reg = 0;        // the temporary (relative)
  uint8_t component = 0;
  int32_t offset = 0;
};

struct Src {
  File file = File::Null;
  uint32_t reg = 0;        // r#, v#, x#, cb#, t#
  Index index;             // cb#[...], x#[...], icb[...]
  std::array<uint8_t, 4> swizzle{0, 1, 2, 3};
  bool negate = false, absolute = false;
  Vec4 literal{};
};

struct Dst {
  File file = File::Null;  // Null: `null`, the result dropped
  uint32_t reg = 0;
  Index index;
  uint8_t mask = 0;
};

struct Op {
  Code code = Code::Nop;
  bool saturate = false;
  uint8_t dstCount = 1, srcCount = 1;
  std::array<Dst, 2> dst;
  std::array<Src, 4> src;
  size_t jump = 0;             // control flow: the op to go to
  size_t line = 0;
  std::string resourceOpcode;  // Resource: "ld_indexable", "sample_l", for the callback
};

struct Program::Impl {
  std::vector<Op> ops;
  uint32_t temps = 0;
  std::map<uint32_t, uint32_t> indexableTemps;  // x# -> elements
  std::map<uint32_t, uint32_t> cbufferRows;
  std::vector<Vec4> immediateConstants;
  std::vector<InputDeclaration> inputs;
  std::map<uint32_t, uint32_t> outputMasks;
  std::optional<uint32_t> position;
};

}  // namespace stereoshift::d3dasm
