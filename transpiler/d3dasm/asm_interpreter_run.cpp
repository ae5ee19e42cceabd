// The execution half of the assembly interpreter (asm_interpreter.h): this turns the decoded
// operations of asm_interpreter.cpp and a Machine's inputs into the Machine's outputs. Every value
// is a 32-bit pattern; an operation reads it as D3D types that operation (float, signed or unsigned
// integer), so a source modifier is a float sign operation for float instructions and an integer
// negate / abs for integer ones, as D3D applies them.
#include "transpiler/d3dasm/asm_interpreter_ops.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace stereoshift::d3dasm {

namespace {

float asFloat(uint32_t u) { return std::bit_cast<float>(u); }
uint32_t asBits(float f) { return std::bit_cast<uint32_t>(f); }
uint32_t mask(bool b) { return b ? 0xFFFFFFFFu : 0u; }

// The sources an operation reads as integers (the rest are floats, or, for mov-like operations,
// bits whose `-` and `|x|` D3D applies as float modifiers).
bool integerSources(Code c) {
  return (c >= Code::Ilt && c <= Code::Umax) || c == Code::Itof || c == Code::Utof ||
         (c >= Code::Bfi && c <= Code::Ibfe) || c == Code::Countbits || c == Code::Bfrev;
}

// The operations whose result is a float, the ones `_sat` clamps.
bool floatResult(Code c) {
  return c <= Code::Sincos || c == Code::Itof || c == Code::Utof || c == Code::Swapc;
}

uint32_t saturate(uint32_t bits) {
  float f = asFloat(bits);
  return asBits(f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f);  // NaN and -0 to +0, as D3D saturates
}

uint32_t floatToInt(float f) {
  if (std::isnan(f)) return 0;
  if (f >= 2147483648.0f) return 0x7FFFFFFFu;
  if (f < -2147483648.0f) return 0x80000000u;
  return static_cast<uint32_t>(static_cast<int32_t>(f));
}

uint32_t floatToUint(float f) {
  if (std::isnan(f) || f <= 0.0f) return 0;
  if (f >= 4294967296.0f) return 0xFFFFFFFFu;
  return static_cast<uint32_t>(f);
}

uint32_t bitfieldExtract(uint32_t width, uint32_t offset, uint32_t value, bool signExtend) {
  width &= 31;
  offset &= 31;
  if (width == 0) return 0;
  if (width + offset < 32) {
    uint32_t up = value << (32 - (width + offset));
    return signExtend ? static_cast<uint32_t>(static_cast<int32_t>(up) >> (32 - width)) : up >> (32 - width);
  }
  return signExtend ? static_cast<uint32_t>(static_cast<int32_t>(value) >> offset) : value >> offset;
}

uint32_t bitReverse(uint32_t v) {
  uint32_t r = 0;
  for (int k = 0; k < 32; ++k) r |= ((v >> k) & 1u) << (31 - k);
  return r;
}

// One component of a float operation. Each step is rounded to float: `mad` is a*b then +c.
uint32_t floatComponent(Code code, const std::array<Vec4, 4>& s, int k) {
  float a = asFloat(s[0][k]), b = asFloat(s[1][k]);
  switch (code) {
    case Code::Add: return asBits(a + b);
    case Code::Mul: return asBits(a * b);
    case Code::Mad: {
      float product = a * b;
      return asBits(product + asFloat(s[2][k]));
    }
    case Code::Div: return asBits(a / b);
    case Code::Min: return asBits(std::fmin(a, b));
    case Code::Max: return asBits(std::fmax(a, b));
    case Code::Rcp: return asBits(1.0f / a);
    case Code::Rsq: return asBits(1.0f / std::sqrt(a));
    case Code::Sqrt: return asBits(std::sqrt(a));
    case Code::Exp: return asBits(std::exp2(a));
    case Code::Log: return asBits(std::log2(a));
    case Code::Frc: return asBits(a - std::floor(a));
    case Code::RoundNe: return asBits(std::nearbyint(a));
    case Code::RoundNi: return asBits(std::floor(a));
    case Code::RoundPi: return asBits(std::ceil(a));
    case Code::RoundZ: return asBits(std::trunc(a));
    case Code::Lt: return mask(a < b);
    case Code::Ge: return mask(a >= b);
    case Code::Eq: return mask(a == b);
    case Code::Ne: return mask(a != b);
    case Code::Ftoi: return floatToInt(a);
    case Code::Ftou: return floatToUint(a);
    default: return 0;
  }
}

uint32_t integerComponent(Code code, const std::array<Vec4, 4>& s, int k) {
  uint32_t a = s[0][k], b = s[1][k], c = s[2][k];
  int32_t ia = static_cast<int32_t>(a), ib = static_cast<int32_t>(b);
  switch (code) {
    case Code::Ilt: return mask(ia < ib);
    case Code::Ige: return mask(ia >= ib);
    case Code::Ieq: return mask(a == b);
    case Code::Ine: return mask(a != b);
    case Code::Ult: return mask(a < b);
    case Code::Uge: return mask(a >= b);
    case Code::Iadd: return a + b;
    case Code::Imad: case Code::Umad: return a * b + c;
    case Code::Ishl: return a << (b & 31);
    case Code::Ishr: return static_cast<uint32_t>(ia >> (b & 31));
    case Code::Ushr: return a >> (b & 31);
    case Code::And: return a & b;
    case Code::Or: return a | b;
    case Code::Xor: return a ^ b;
    case Code::Not: return ~a;
    case Code::Ineg: return 0u - a;
    case Code::Imin: return static_cast<uint32_t>(std::min(ia, ib));
    case Code::Imax: return static_cast<uint32_t>(std::max(ia, ib));
    case Code::Umin: return std::min(a, b);
    case Code::Umax: return std::max(a, b);
    case Code::Itof: return asBits(static_cast<float>(ia));
    case Code::Utof: return asBits(static_cast<float>(a));
    case Code::Ubfe: return bitfieldExtract(a, b, c, false);
    case Code::Ibfe: return bitfieldExtract(a, b, c, true);
    case Code::Bfi: {
      uint32_t width = a & 31, offset = b & 31;
      uint32_t bits = ((1u << width) - 1u) << offset;
      return ((c << offset) & bits) | (s[3][k] & ~bits);
    }
    case Code::Countbits: return static_cast<uint32_t>(std::popcount(a));
    case Code::Bfrev: return bitReverse(a);
    default: return 0;
  }
}

struct State {
  const Program::Impl& program;
  Machine& machine;
  std::vector<Vec4> temps;
  std::map<uint32_t, std::vector<Vec4>> indexable;

  int64_t element(const Index& index) const {
    int64_t base = index.relative ? static_cast<int32_t>(temps[index.reg][index.component]) : 0;
    return base + index.offset;
  }

  static Vec4 row(const std::vector<Vec4>& rows, int64_t element) {
    return element >= 0 && element < static_cast<int64_t>(rows.size()) ? rows[static_cast<size_t>(element)] : Vec4{};
  }

  Vec4 raw(const Src& s) {
    switch (s.file) {
      case File::Temp: return temps[s.reg];
      case File::Input: {
        auto it = machine.inputs.find(s.reg);
        return it != machine.inputs.end() ? it->second : Vec4{0, 0, 0, asBits(1.0f)};
      }
      case File::IndexableTemp: return row(indexable[s.reg], element(s.index));
      case File::ConstantBuffer: {
        auto it = machine.cbuffers.find(s.reg);
        return it == machine.cbuffers.end() ? Vec4{} : row(it->second, element(s.index));
      }
      case File::ImmediateCB: return row(program.immediateConstants, element(s.index));
      case File::Literal: return s.literal;
      default: return Vec4{};
    }
  }

  Vec4 fetch(const Src& s, bool integer) {
    Vec4 r = raw(s), out;
    for (int k = 0; k < 4; ++k) {
      uint32_t v = r[s.swizzle[k]];
      if (s.absolute) v = integer ? (static_cast<int32_t>(v) < 0 ? 0u - v : v) : v & 0x7FFFFFFFu;
      if (s.negate) v = integer ? 0u - v : v ^ 0x80000000u;
      out[k] = v;
    }
    return out;
  }

  void write(const Dst& d, const Vec4& value, bool saturateFloat) {
    Vec4* target = nullptr;
    if (d.file == File::Temp) target = &temps[d.reg];
    else if (d.file == File::Output) target = &machine.outputs[d.reg];
    else if (d.file == File::IndexableTemp) {
      std::vector<Vec4>& rows = indexable[d.reg];
      int64_t e = element(d.index);
      if (e >= 0 && e < static_cast<int64_t>(rows.size())) target = &rows[static_cast<size_t>(e)];
    }
    if (!target) return;  // null, or an indexable element out of range (D3D drops the write)
    for (int k = 0; k < 4; ++k)
      if ((d.mask >> k) & 1) (*target)[k] = saturateFloat ? saturate(value[k]) : value[k];
  }

  void resource(const Op& op) {
    bool integerCoordinate = op.resourceOpcode.starts_with("ld") || op.resourceOpcode.starts_with("resinfo");
    Vec4 coordinate = fetch(op.src[0], integerCoordinate);
    Vec4 texel = machine.resource ? machine.resource(op.src[1].reg, coordinate, op.resourceOpcode) : Vec4{};
    Vec4 swizzled;
    for (int k = 0; k < 4; ++k) swizzled[k] = texel[op.src[1].swizzle[k]];
    write(op.dst[0], swizzled, op.saturate);
  }

  void alu(const Op& op) {
    std::array<Vec4, 4> s{};
    const bool integer = integerSources(op.code);
    for (int k = 0; k < op.srcCount; ++k) {
      bool condition = k == 0 && (op.code == Code::Movc || op.code == Code::Swapc);
      s[k] = fetch(op.src[k], integer || condition);
    }
    Vec4 first{}, second{};
    for (int k = 0; k < 4; ++k) {
      switch (op.code) {
        case Code::Mov: first[k] = s[0][k]; break;
        case Code::Movc: first[k] = s[0][k] ? s[1][k] : s[2][k]; break;
        case Code::Swapc:
          first[k] = s[0][k] ? s[2][k] : s[1][k];
          second[k] = s[0][k] ? s[1][k] : s[2][k];
          break;
        case Code::Dp2: case Code::Dp3: case Code::Dp4: {
          int n = op.code == Code::Dp2 ? 2 : op.code == Code::Dp3 ? 3 : 4;
          float sum = asFloat(s[0][0]) * asFloat(s[1][0]);
          for (int c = 1; c < n; ++c) {
            float product = asFloat(s[0][c]) * asFloat(s[1][c]);
            sum = sum + product;
          }
          first[k] = asBits(sum);
          break;
        }
        case Code::Sincos:
          first[k] = asBits(std::sin(asFloat(s[0][k])));
          second[k] = asBits(std::cos(asFloat(s[0][k])));
          break;
        case Code::Imul: case Code::Umul: {
          uint64_t p = op.code == Code::Imul
                           ? static_cast<uint64_t>(int64_t{static_cast<int32_t>(s[0][k])} * static_cast<int32_t>(s[1][k]))
                           : uint64_t{s[0][k]} * s[1][k];
          first[k] = static_cast<uint32_t>(p >> 32);
          second[k] = static_cast<uint32_t>(p);
          break;
        }
        case Code::Udiv:
          first[k] = s[1][k] ? s[0][k] / s[1][k] : 0xFFFFFFFFu;
          second[k] = s[1][k] ? s[0][k] % s[1][k] : 0xFFFFFFFFu;
          break;
        default: first[k] = integer ? integerComponent(op.code, s, k) : floatComponent(op.code, s, k);
      }
    }
    const bool sat = op.saturate && floatResult(op.code);
    write(op.dst[0], first, sat);
    if (op.dstCount == 2) write(op.dst[1], second, sat);
  }
};

}  // namespace

RunResult Program::run(Machine& machine) const {
  const Impl& p = *impl_;
  State state{p, machine, std::vector<Vec4>(p.temps, Vec4{}), {}};
  for (const auto& [reg, size] : p.indexableTemps) state.indexable[reg].assign(size, Vec4{});
  machine.outputs.clear();
  RunResult result;
  uint64_t executed = 0;
  size_t pc = 0;
  while (pc < p.ops.size()) {
    const Op& op = p.ops[pc];
    if (++executed > machine.instructionLimit) {
      result.limitReached = true;
      result.line = op.line;
      result.error = "the instruction limit (" + std::to_string(machine.instructionLimit) + ") was reached";
      return result;
    }
    auto holds = [&](bool nonzero) { return (state.fetch(op.src[0], true)[0] != 0) == nonzero; };
    switch (op.code) {
      case Code::IfNz: case Code::IfZ: pc = holds(op.code == Code::IfNz) ? pc + 1 : op.jump; break;
      case Code::Else: case Code::Endloop: case Code::Break: case Code::Continue: pc = op.jump; break;
      case Code::BreakcNz: case Code::BreakcZ: pc = holds(op.code == Code::BreakcNz) ? op.jump : pc + 1; break;
      case Code::ContinuecNz: case Code::ContinuecZ:
        pc = holds(op.code == Code::ContinuecNz) ? op.jump : pc + 1;
        break;
      case Code::Ret: result.ok = true; return result;
      case Code::RetcNz: case Code::RetcZ:
        if (holds(op.code == Code::RetcNz)) {
          result.ok = true;
          return result;
        }
        ++pc;
        break;
      case Code::Endif: case Code::Loop: case Code::Nop: ++pc; break;
      case Code::Resource: state.resource(op); ++pc; break;
      default: state.alu(op); ++pc;
    }
  }
  result.ok = true;  // the end of the program returns
  return result;
}

}  // namespace stereoshift::d3dasm
