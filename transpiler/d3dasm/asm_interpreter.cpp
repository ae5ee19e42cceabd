// The interpreter of SM4/SM5 vertex-shader assembly (asm_interpreter.h): this turns the parsed lines
// of a shader into a list of decoded operations (each operand read once, here, so that a run only
// moves bits), and runs that list on a Machine. The execution half is asm_interpreter_run.cpp.
#include "transpiler/d3dasm/asm_interpreter_ops.h"

#include "transpiler/source/identifiers.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace stereoshift::d3dasm {

namespace {

struct OpInfo {
  Code code;
  uint8_t dsts, srcs;  // srcs 255: any number (resource reads)
};

const std::map<std::string_view, OpInfo>& opTable() {
  static const std::map<std::string_view, OpInfo> table = {
      {"mov", {Code::Mov, 1, 1}},          {"movc", {Code::Movc, 1, 3}},       {"add", {Code::Add, 1, 2}},
      {"mul", {Code::Mul, 1, 2}},          {"mad", {Code::Mad, 1, 3}},         {"dp2", {Code::Dp2, 1, 2}},
      {"dp3", {Code::Dp3, 1, 2}},          {"dp4", {Code::Dp4, 1, 2}},         {"div", {Code::Div, 1, 2}},
      {"min", {Code::Min, 1, 2}},          {"max", {Code::Max, 1, 2}},         {"rcp", {Code::Rcp, 1, 1}},
      {"rsq", {Code::Rsq, 1, 1}},          {"sqrt", {Code::Sqrt, 1, 1}},       {"exp", {Code::Exp, 1, 1}},
      {"log", {Code::Log, 1, 1}},          {"frc", {Code::Frc, 1, 1}},         {"round_ne", {Code::RoundNe, 1, 1}},
      {"round_ni", {Code::RoundNi, 1, 1}}, {"round_pi", {Code::RoundPi, 1, 1}}, {"round_z", {Code::RoundZ, 1, 1}},
      {"sincos", {Code::Sincos, 2, 1}},    {"lt", {Code::Lt, 1, 2}},           {"ge", {Code::Ge, 1, 2}},
      {"eq", {Code::Eq, 1, 2}},            {"ne", {Code::Ne, 1, 2}},           {"ilt", {Code::Ilt, 1, 2}},
      {"ige", {Code::Ige, 1, 2}},          {"ieq", {Code::Ieq, 1, 2}},         {"ine", {Code::Ine, 1, 2}},
      {"ult", {Code::Ult, 1, 2}},          {"uge", {Code::Uge, 1, 2}},         {"iadd", {Code::Iadd, 1, 2}},
      {"imul", {Code::Imul, 2, 2}},        {"umul", {Code::Umul, 2, 2}},       {"imad", {Code::Imad, 1, 3}},
      {"umad", {Code::Umad, 1, 3}},        {"udiv", {Code::Udiv, 2, 2}},       {"ishl", {Code::Ishl, 1, 2}},
      {"ishr", {Code::Ishr, 1, 2}},        {"ushr", {Code::Ushr, 1, 2}},       {"and", {Code::And, 1, 2}},
      {"or", {Code::Or, 1, 2}},            {"xor", {Code::Xor, 1, 2}},         {"not", {Code::Not, 1, 1}},
      {"ineg", {Code::Ineg, 1, 1}},        {"imin", {Code::Imin, 1, 2}},       {"imax", {Code::Imax, 1, 2}},
      {"umin", {Code::Umin, 1, 2}},        {"umax", {Code::Umax, 1, 2}},       {"itof", {Code::Itof, 1, 1}},
      {"utof", {Code::Utof, 1, 1}},        {"ftoi", {Code::Ftoi, 1, 1}},       {"ftou", {Code::Ftou, 1, 1}},
      {"bfi", {Code::Bfi, 1, 4}},          {"ubfe", {Code::Ubfe, 1, 3}},       {"ibfe", {Code::Ibfe, 1, 3}},
      {"swapc", {Code::Swapc, 2, 3}},      {"countbits", {Code::Countbits, 1, 1}}, {"bfrev", {Code::Bfrev, 1, 1}},
      {"if_nz", {Code::IfNz, 0, 1}},       {"if_z", {Code::IfZ, 0, 1}},        {"else", {Code::Else, 0, 0}},
      {"endif", {Code::Endif, 0, 0}},      {"loop", {Code::Loop, 0, 0}},       {"endloop", {Code::Endloop, 0, 0}},
      {"break", {Code::Break, 0, 0}},      {"breakc_nz", {Code::BreakcNz, 0, 1}}, {"breakc_z", {Code::BreakcZ, 0, 1}},
      {"continue", {Code::Continue, 0, 0}}, {"continuec_nz", {Code::ContinuecNz, 0, 1}},
      {"continuec_z", {Code::ContinuecZ, 0, 1}}, {"ret", {Code::Ret, 0, 0}}, {"retc_nz", {Code::RetcNz, 0, 1}},
      {"retc_z", {Code::RetcZ, 0, 1}},     {"nop", {Code::Nop, 0, 0}},
  };
  return table;
}

// Reads like texture loads: `ld`, `ld_indexable`, `ld_structured`, `sample_l`, `resinfo`, ... The
// interpreter does not model resources; the Machine's callback answers them.
bool isResourceRead(std::string_view base) {
  return base.starts_with("ld") || base.starts_with("sample") || base.starts_with("resinfo") ||
         base.starts_with("gather4") || base == "bufinfo";
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

uint32_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

// One number of a literal or of the immediate constant buffer, as the disassembler writes it: a
// float (`1.000000`, `-0.500000`, `1.#INF00`), a hex pattern (`0x3f800000`) or an integer (`3`, `-1`).
std::optional<uint32_t> parseNumber(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  bool negative = text.front() == '-';
  std::string_view digits = negative || text.front() == '+' ? text.substr(1) : text;
  if (digits.starts_with("0x") || digits.starts_with("0X")) {
    uint32_t value = 0;
    auto [end, ec] = std::from_chars(digits.data() + 2, digits.data() + digits.size(), value, 16);
    if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    return negative ? 0u - value : value;
  }
  if (digits.find("#INF") != std::string_view::npos || digits == "inf")
    return floatBits(negative ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity());
  if (digits.find("#IND") != std::string_view::npos || digits.find("#QNAN") != std::string_view::npos || digits == "nan")
    return negative ? 0xFFC00000u : 0x7FC00000u;
  std::string owned(text);
  char* end = nullptr;
  if (digits.find_first_of(".eE") != std::string_view::npos) {
    float value = std::strtof(owned.c_str(), &end);
    if (end != owned.c_str() + owned.size()) return std::nullopt;
    return floatBits(value);
  }
  long long value = std::strtoll(owned.c_str(), &end, 10);
  if (end != owned.c_str() + owned.size()) return std::nullopt;
  return static_cast<uint32_t>(value);
}

std::optional<uint32_t> parseCount(std::string_view text) {
  uint32_t n = 0;
  text = trim(text);
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return n;
}

int componentOf(char c) {
  switch (c) {
    case 'x': case 'r': return 0;
    case 'y': case 'g': return 1;
    case 'z': case 'b': return 2;
    case 'w': case 'a': return 3;
    default: return -1;
  }
}

// A source swizzle: four letters select per component; one letter is a scalar, replicated. Two or
// three letters in increasing order are a component mask (each component where it is, as the
// bytecode's mask mode reads them); otherwise the last letter is repeated.
bool parseSwizzle(std::string_view letters, std::array<uint8_t, 4>* swizzle) {
  if (letters.empty() || letters.size() > 4) return false;
  std::array<int, 4> c{};
  for (size_t k = 0; k < letters.size(); ++k)
    if ((c[k] = componentOf(letters[k])) < 0) return false;
  bool increasing = true;
  for (size_t k = 1; k < letters.size(); ++k) increasing = increasing && c[k] > c[k - 1];
  if (letters.size() == 4 || letters.size() == 1 || !increasing) {
    for (size_t k = 0; k < 4; ++k) (*swizzle)[k] = static_cast<uint8_t>(c[std::min(k, letters.size() - 1)]);
  } else {
    for (size_t k = 0; k < 4; ++k) (*swizzle)[k] = static_cast<uint8_t>(c[0]);
    for (size_t k = 0; k < letters.size(); ++k) (*swizzle)[c[k]] = static_cast<uint8_t>(c[k]);
  }
  return true;
}

std::optional<uint8_t> parseMask(std::string_view letters) {
  if (letters.empty()) return uint8_t{0xF};
  uint8_t mask = 0;
  for (char l : letters) {
    int c = componentOf(l);
    if (c < 0 || (mask >> c) & 1) return std::nullopt;
    mask |= static_cast<uint8_t>(1u << c);
  }
  return mask;
}

// Decodes the operands of one line; each failure says what and where (the operand's column).
struct OperandReader {
  const Program::Impl& program;
  const AsmLine& line;
  AsmError* error;

  bool fail(const Operand& operand, const std::string& why) {
    *error = errorAt(line.number, operand.column, why);
    return false;
  }

  // `4`, `r0.x`, `r0.x + 4`: an index in brackets.
  bool readIndex(const Operand& operand, std::string_view text, Index* index) {
    text = trim(text);
    size_t plus = text.find('+');
    std::string_view head = trim(text.substr(0, plus));
    if (!head.empty() && head.front() == 'r') {
      size_t dot = head.find('.');
      auto reg = parseCount(head.substr(1, dot == std::string_view::npos ? std::string_view::npos : dot - 1));
      int component = dot == std::string_view::npos || dot + 2 != head.size() ? -1 : componentOf(head[dot + 1]);
      if (!reg || component < 0)
        return fail(operand, "a relative index reads one component of a temporary (r0.x + 4), not '" + std::string(text) + "'");
      if (*reg >= program.temps)
        return fail(operand, "r" + std::to_string(*reg) + " is beyond dcl_temps " + std::to_string(program.temps));
      index->relative = true;
      index->reg = *reg;
      index->component = static_cast<uint8_t>(component);
      if (plus == std::string_view::npos) return true;
      head = trim(text.substr(plus + 1));
    } else if (plus != std::string_view::npos) {
      return fail(operand, "an index is an integer or r#.c + integer, not '" + std::string(text) + "'");
    }
    auto offset = parseNumber(head);
    if (!offset) return fail(operand, "an index is an integer or r#.c + integer, not '" + std::string(text) + "'");
    index->offset = static_cast<int32_t>(*offset);
    return true;
  }

  bool readLiteral(const Operand& operand, std::string_view body, Src* src) {
    std::vector<uint32_t> values;
    size_t at = 0;
    while (at <= body.size()) {
      size_t comma = body.find(',', at);
      if (comma == std::string_view::npos) comma = body.size();
      auto value = parseNumber(body.substr(at, comma - at));
      if (!value) return fail(operand, "'" + std::string(body.substr(at, comma - at)) + "' is not a number");
      values.push_back(*value);
      at = comma + 1;
    }
    if (values.size() != 1 && values.size() != 4) return fail(operand, "a literal holds one or four numbers");
    src->file = File::Literal;
    for (size_t k = 0; k < 4; ++k) src->literal[k] = values[values.size() == 1 ? 0 : k];
    return true;
  }

  // The register part of an operand (`r0`, `cb0[r0.x + 4]`, `x1[2]`, `icb[r1.y + 0]`, `t125`), then
  // its swizzle or mask letters in *letters.
  bool readRegister(const Operand& operand, std::string_view text, File* file, uint32_t* reg, Index* index,
                    std::string_view* letters) {
    size_t nameEnd = 0;
    while (nameEnd < text.size() && text[nameEnd] >= 'a' && text[nameEnd] <= 'z') ++nameEnd;
    std::string_view name = text.substr(0, nameEnd), rest = text.substr(nameEnd);
    size_t digitsEnd = 0;
    while (digitsEnd < rest.size() && isDecimalDigit(rest[digitsEnd])) ++digitsEnd;
    const std::string register_ = std::string(text.substr(0, text.find_first_of(".[")));
    static const std::map<std::string_view, File> files = {
        {"r", File::Temp}, {"v", File::Input}, {"o", File::Output}, {"x", File::IndexableTemp},
        {"cb", File::ConstantBuffer}, {"icb", File::ImmediateCB}, {"t", File::Resource}, {"s", File::Sampler}};
    auto found = files.find(name);
    bool numbered = found != files.end() && found->second != File::ImmediateCB;
    if (found == files.end() || (numbered && digitsEnd == 0) || (!numbered && digitsEnd != 0) ||
        (digitsEnd < rest.size() && rest[digitsEnd] != '.' && rest[digitsEnd] != '['))
      return fail(operand, "'" + register_ + "' is not a register of a vertex shader the interpreter runs");
    *file = found->second;
    *reg = numbered ? *parseCount(rest.substr(0, digitsEnd)) : 0;
    rest = rest.substr(digitsEnd);
    bool indexed = *file == File::ConstantBuffer || *file == File::ImmediateCB || *file == File::IndexableTemp;
    if (!rest.empty() && rest.front() == '[') {
      size_t close = rest.find(']');
      if (!indexed) return fail(operand, "'" + register_ + "' is indexed, which the interpreter does not run");
      if (close == std::string_view::npos || !readIndex(operand, rest.substr(1, close - 1), index)) return false;
      rest = rest.substr(close + 1);
      if (!rest.empty() && rest.front() == '[')
        return fail(operand, "two-dimensional indexing (SM5.1) is not run by the interpreter");
    } else if (indexed) {
      return fail(operand, "'" + register_ + "' needs an index in brackets");
    }
    if (!rest.empty() && rest.front() != '.') return fail(operand, "unexpected '" + std::string(rest) + "'");
    *letters = rest.empty() ? std::string_view() : rest.substr(1);
    return checkRange(operand, *file, *reg);
  }

  bool checkRange(const Operand& operand, File file, uint32_t reg) {
    if (file == File::Temp && reg >= program.temps)
      return fail(operand, "r" + std::to_string(reg) + " is beyond dcl_temps " + std::to_string(program.temps));
    if (file == File::IndexableTemp && !program.indexableTemps.count(reg))
      return fail(operand, "x" + std::to_string(reg) + " is not declared (dcl_indexableTemp)");
    if (file == File::ConstantBuffer && !program.cbufferRows.count(reg))
      return fail(operand, "cb" + std::to_string(reg) + " is not declared (dcl_constantbuffer)");
    return true;
  }

  bool readSrc(const Operand& operand, Src* src) {
    std::string_view text = operand.text;
    if (text.starts_with("-")) {
      src->negate = true;
      text.remove_prefix(1);
    }
    if (text.size() >= 2 && text.front() == '|' && text.back() == '|') {
      src->absolute = true;
      text = text.substr(1, text.size() - 2);
    }
    if (text.starts_with("l(") && text.ends_with(")")) return readLiteral(operand, text.substr(2, text.size() - 3), src);
    if (text == "null") return fail(operand, "null is not a source");
    std::string_view letters;
    if (!readRegister(operand, text, &src->file, &src->reg, &src->index, &letters)) return false;
    if (src->file == File::Output) return fail(operand, "an output register is not readable (SM4+)");
    if (!letters.empty() && !parseSwizzle(letters, &src->swizzle))
      return fail(operand, "'" + std::string(letters) + "' is not a swizzle");
    return true;
  }

  bool readDst(const Operand& operand, Dst* dst) {
    if (operand.text == "null") return true;
    std::string_view letters;
    File file;
    if (!readRegister(operand, operand.text, &file, &dst->reg, &dst->index, &letters)) return false;
    if (file != File::Temp && file != File::Output && file != File::IndexableTemp)
      return fail(operand, "'" + operand.text + "' is not a register an instruction writes");
    auto mask = parseMask(letters);
    if (!mask) return fail(operand, "'" + std::string(letters) + "' is not a write mask");
    dst->file = file;
    dst->mask = *mask;
    return true;
  }
};

// The brace block of dcl_immediateConstantBuffer, over its lines: groups of four numbers.
bool readImmediateConstants(const AsmText& text, size_t first, std::vector<Vec4>* rows, AsmError* error) {
  const AsmLine& head = text.lines[first];
  std::string block = head.operands.empty() ? "" : head.operands[0].text;
  for (size_t k = first + 1; k <= head.lastLine; ++k) block += " " + text.lines[k].text;
  size_t at = block.find('{');
  while ((at = block.find('{', at + 1)) != std::string::npos) {
    size_t close = block.find('}', at);
    if (close == std::string::npos) break;
    std::string_view group = std::string_view(block).substr(at + 1, close - at - 1);
    Vec4 row{};
    size_t component = 0, from = 0;
    while (from <= group.size() && component < 4) {
      size_t comma = std::min(group.find(',', from), group.size());
      auto value = parseNumber(group.substr(from, comma - from));
      if (!value) {
        *error = errorAt(head.number, 1, "'" + std::string(group) + "' in the immediate constant buffer is not four numbers");
        return false;
      }
      row[component++] = *value;
      from = comma + 1;
    }
    rows->push_back(row);
    at = close;
  }
  return true;
}

bool readDeclaration(const AsmText& text, size_t k, Program::Impl* p, AsmError* error) {
  const AsmLine& line = text.lines[k];
  const std::string base = line.baseOpcode();
  const auto& ops = line.operands;
  auto bad = [&](const std::string& why) {
    *error = errorAt(line.number, ops.empty() ? 1 : ops[0].column, why);
    return false;
  };
  auto numbered = [&](std::string_view prefix, size_t operand, uint32_t* n, std::string* letters) {
    std::string_view t = ops[operand].text;
    if (!t.starts_with(prefix)) return false;
    t.remove_prefix(prefix.size());
    size_t end = t.find_first_of(".[");
    auto value = parseCount(t.substr(0, end));
    if (!value) return false;
    *n = *value;
    if (letters) *letters = end == std::string_view::npos ? "" : std::string(t.substr(end + 1));
    return true;
  };
  uint32_t n = 0;
  std::string rest;
  if (base == "dcl_temps") {
    auto count = ops.size() == 1 ? parseCount(ops[0].text) : std::nullopt;
    if (!count) return bad("dcl_temps takes a count");
    p->temps = *count;
  } else if (base == "dcl_indexableTemp") {
    if (ops.size() < 1 || !numbered("x", 0, &n, &rest)) return bad("dcl_indexableTemp x#[size], components");
    auto size = parseCount(std::string_view(rest).substr(0, rest.find(']')));
    if (!size) return bad("dcl_indexableTemp x#[size], components");
    p->indexableTemps[n] = *size;
  } else if (base == "dcl_constantbuffer") {
    if (ops.empty() || !numbered("cb", 0, &n, &rest)) return bad("dcl_constantbuffer cb#[rows]");
    auto rows = parseCount(std::string_view(rest).substr(0, rest.find(']')));
    if (!rows) return bad("dcl_constantbuffer cb#[rows]");
    p->cbufferRows[n] = *rows;
  } else if (base == "dcl_immediateConstantBuffer") {
    return readImmediateConstants(text, k, &p->immediateConstants, error);
  } else if (base == "dcl_input" || base == "dcl_input_sgv" || base == "dcl_input_siv") {
    if (ops.empty() || !numbered("v", 0, &n, &rest))
      return bad("'" + (ops.empty() ? std::string() : ops[0].text) + "' is not a vertex shader input the interpreter runs");
    auto mask = parseMask(rest);
    if (!mask) return bad("'" + rest + "' is not a mask");
    p->inputs.push_back({n, *mask, ops.size() > 1 ? ops[1].text : ""});
  } else if (base == "dcl_output" || base == "dcl_output_siv" || base == "dcl_output_sgv") {
    if (ops.empty() || !numbered("o", 0, &n, &rest)) return bad("'" + (ops.empty() ? std::string() : ops[0].text) + "' is not an output");
    auto mask = parseMask(rest);
    if (!mask) return bad("'" + rest + "' is not a mask");
    p->outputMasks[n] |= *mask;
    if (ops.size() > 1 && ops[1].text == "position") p->position = n;
  } else if (base == "dcl_input_ps" || base == "dcl_input_ps_siv" || base == "dcl_input_ps_sgv") {
    // `dcl_input_ps linear v1.xy`, `dcl_input_ps_siv linear noperspective v0.xy, position`: the
    // interpolation words first, then the register, then the system value.
    size_t reg = 0;
    while (reg < ops.size() && !numbered("v", reg, &n, &rest)) ++reg;
    if (reg == ops.size()) return bad("'" + line.text.substr(line.indent.size()) + "' declares no v# input");
    auto mask = parseMask(rest);
    if (!mask) return bad("'" + rest + "' is not a mask");
    p->inputs.push_back({n, *mask, reg + 1 < ops.size() ? ops[reg + 1].text : ""});
  } else if (base.starts_with("dcl_input_ps") || base.starts_with("dcl_hs") || base.starts_with("dcl_gs") ||
             base == "dcl_function_body" || base == "dcl_function_table" || base == "dcl_interface") {
    return bad("'" + base + "' declares what the vertex-shader interpreter does not run");
  }
  return true;  // resources, samplers, global flags, index ranges: nothing to run
}

// Matches if/else/endif and loop/endloop; break and continue jump to their loop's end and start.
struct FlowMatcher {
  struct Open {
    Code code;
    size_t op;
    std::vector<size_t> breaks;
  };
  std::vector<Open> open;

  std::string add(std::vector<Op>& ops, size_t k) {
    Op& op = ops[k];
    auto innermostLoop = [&]() -> Open* {
      for (auto it = open.rbegin(); it != open.rend(); ++it)
        if (it->code == Code::Loop) return &*it;
      return nullptr;
    };
    switch (op.code) {
      case Code::IfNz: case Code::IfZ: case Code::Loop: open.push_back({op.code, k, {}}); break;
      case Code::Else:
        if (open.empty() || (open.back().code != Code::IfNz && open.back().code != Code::IfZ)) return "else without if";
        ops[open.back().op].jump = k + 1;
        open.back() = {Code::Else, k, {}};
        break;
      case Code::Endif:
        if (open.empty() || open.back().code == Code::Loop) return "endif without if";
        ops[open.back().op].jump = k;
        open.pop_back();
        break;
      case Code::Endloop:
        if (open.empty() || open.back().code != Code::Loop) return "endloop without loop";
        op.jump = open.back().op + 1;
        for (size_t b : open.back().breaks) ops[b].jump = k + 1;
        open.pop_back();
        break;
      case Code::Break: case Code::BreakcNz: case Code::BreakcZ:
        if (!innermostLoop()) return "break outside a loop";
        innermostLoop()->breaks.push_back(k);
        break;
      case Code::Continue: case Code::ContinuecNz: case Code::ContinuecZ:
        if (!innermostLoop()) return "continue outside a loop";
        op.jump = innermostLoop()->op + 1;
        break;
      default: break;
    }
    return "";
  }
};

// An instruction the interpreter does not run, for an analysis: its first operand written when it is
// a register, the others read where they are registers, literals or constant-buffer elements.
bool decodeOpaque(const AsmLine& line, Program::Impl* p) {
  Op op;
  op.code = Code::Opaque;
  op.line = line.number;
  AsmError ignored;
  OperandReader reader{*p, line, &ignored};
  op.dstCount = 0;
  op.srcCount = 0;
  size_t first = 0;
  if (!line.operands.empty() && reader.readDst(line.operands[0], &op.dst[0])) {
    op.dstCount = 1;
    first = 1;
  }
  for (size_t k = first; k < line.operands.size() && op.srcCount < 4; ++k)
    if (reader.readSrc(line.operands[k], &op.src[op.srcCount])) ++op.srcCount;
  p->ops.push_back(op);
  return true;
}

bool decodeInstruction(const AsmLine& line, Program::Impl* p, AsmError* error, DecodeFor purpose) {
  const std::string base = line.baseOpcode();
  Op op;
  op.line = line.number;
  op.saturate = line.saturates();
  OperandReader reader{*p, line, error};
  auto refuse = [&](const std::string& why) {
    *error = errorAt(line.number, line.indent.size() + 1, why);
    return false;
  };
  if (base == "label" || base == "call" || base == "callc_nz" || base == "callc_z" || base == "fcall")
    return refuse("'" + base + "': subroutines are not run by the interpreter");
  if (base == "switch" || base == "case" || base == "default" || base == "endswitch")
    return refuse("'" + base + "': switch is not run by the interpreter");
  if (isResourceRead(base)) {
    op.code = Code::Resource;
    op.resourceOpcode = base;
    if (line.operands.size() < 3) return refuse("'" + base + "' needs a destination, a coordinate and a resource");
    if (!reader.readDst(line.operands[0], &op.dst[0]) || !reader.readSrc(line.operands[1], &op.src[0])) return false;
    for (size_t k = 2; k < line.operands.size() && op.srcCount == 1; ++k) {
      if (!line.operands[k].text.starts_with("t")) continue;
      if (!reader.readSrc(line.operands[k], &op.src[1])) return false;
      op.srcCount = 2;
    }
    if (op.srcCount != 2 || op.src[1].file != File::Resource) return refuse("'" + base + "' reads no t# resource");
    p->ops.push_back(op);
    return true;
  }
  auto found = opTable().find(base);
  const bool runs = found != opTable().end() && line.operands.size() == size_t(found->second.dsts) + found->second.srcs;
  if (!runs && purpose == DecodeFor::Analysis) return decodeOpaque(line, p);
  if (found == opTable().end()) return refuse("'" + base + "' is not an instruction the interpreter runs");
  const OpInfo& info = found->second;
  if (line.operands.size() != size_t(info.dsts) + info.srcs)
    return refuse("'" + base + "' takes " + std::to_string(info.dsts + info.srcs) + " operands, not " +
                  std::to_string(line.operands.size()));
  op.code = info.code;
  op.dstCount = info.dsts;
  op.srcCount = info.srcs;
  for (uint8_t k = 0; k < info.dsts; ++k)
    if (!reader.readDst(line.operands[k], &op.dst[k])) return false;
  for (uint8_t k = 0; k < info.srcs; ++k)
    if (!reader.readSrc(line.operands[info.dsts + k], &op.src[k])) return false;
  p->ops.push_back(op);
  return true;
}

}  // namespace

std::unique_ptr<Program> Program::decode(const AsmText& text, AsmError* error, DecodeFor purpose) {
  auto impl = std::make_unique<Impl>();
  std::optional<Stage> stage = stageOfShaderModel(text.model);
  if ((stage != Stage::Vertex && stage != Stage::Fragment) || text.model.major < 4) {
    *error = errorAt(text.lines.empty() ? 0 : text.lines[text.modelLine].number, 1,
                     text.model.text + ": the interpreter runs SM4 and SM5 vertex and pixel shaders");
    return nullptr;
  }
  // Declarations first: an instruction's registers are checked against them.
  for (size_t k = 0; k < text.lines.size(); ++k)
    if (text.lines[k].kind == LineKind::Declaration && !readDeclaration(text, k, impl.get(), error)) return nullptr;
  FlowMatcher flow;
  for (const AsmLine& line : text.lines) {
    if (line.kind != LineKind::Instruction) continue;
    if (!decodeInstruction(line, impl.get(), error, purpose)) return nullptr;
    if (std::string why = flow.add(impl->ops, impl->ops.size() - 1); !why.empty()) {
      *error = errorAt(line.number, line.indent.size() + 1, why);
      return nullptr;
    }
  }
  if (!flow.open.empty()) {
    const Op& unclosed = impl->ops[flow.open.back().op];
    *error = errorAt(unclosed.line, 1, flow.open.back().code == Code::Loop ? "loop without endloop" : "if without endif");
    return nullptr;
  }
  return std::unique_ptr<Program>(new Program(std::move(impl)));
}

Program::Program(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Program::~Program() = default;

const std::vector<InputDeclaration>& Program::inputs() const { return impl_->inputs; }
const std::map<uint32_t, uint32_t>& Program::cbufferSizes() const { return impl_->cbufferRows; }
const std::map<uint32_t, uint32_t>& Program::outputMasks() const { return impl_->outputMasks; }
std::optional<uint32_t> Program::positionOutput() const { return impl_->position; }

}  // namespace stereoshift::d3dasm
