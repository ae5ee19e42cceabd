// See asm_wellformed.h.
#include "transpiler/d3dasm/asm_wellformed.h"

#include <cctype>
#include <regex>
#include <set>
#include <string_view>

namespace stereoshift::d3dasm {

namespace {

// The instructions of shader models 4.0 to 5.0 (D3D10 / D3D11 tokenized programs), by the
// mnemonic the disassembler writes without its modifiers. Declarations (`dcl_*`) and the hull
// shader's phase markers are lines of their own kind.
const std::set<std::string, std::less<>>& instructions() {
  static const std::set<std::string, std::less<>> names = {
      // arithmetic, comparison, conversion (4.0)
      "add", "and", "div", "dp2", "dp3", "dp4", "eq", "exp", "frc", "ftoi", "ftou", "ge", "iadd", "ieq", "ige", "ilt",
      "imad", "imax", "imin", "imul", "ine", "ineg", "ishl", "ishr", "itof", "log", "lt", "mad", "max", "min", "mov",
      "movc", "mul", "ne", "nop", "not", "or", "round_ne", "round_ni", "round_pi", "round_z", "rsq", "sincos", "sqrt",
      "udiv", "uge", "ult", "umad", "umax", "umin", "umul", "ushr", "utof", "xor", "deriv_rtx", "deriv_rty",
      // flow control (4.0)
      "break", "breakc", "call", "callc", "case", "continue", "continuec", "default", "discard", "else", "endif",
      "endloop", "endswitch", "if", "label", "loop", "ret", "retc", "switch",
      // geometry (4.0, 5.0 streams)
      "cut", "emit", "emitthencut", "cut_stream", "emit_stream", "emitthencut_stream",
      // resources (4.0, 4.1)
      "ld", "ld_ms", "resinfo", "sample", "sample_b", "sample_c", "sample_c_lz", "sample_d", "sample_l", "lod",
      "gather4", "samplepos", "sampleinfo",
      // 5.0
      "bufinfo", "deriv_rtx_coarse", "deriv_rtx_fine", "deriv_rty_coarse", "deriv_rty_fine", "gather4_c", "gather4_po",
      "gather4_po_c", "rcp", "f32tof16", "f16tof32", "uaddc", "usubb", "countbits", "firstbit_hi", "firstbit_lo",
      "firstbit_shi", "ubfe", "ibfe", "bfi", "bfrev", "swapc", "fcall", "ld_uav_typed", "store_uav_typed", "ld_raw",
      "store_raw", "ld_structured", "store_structured", "atomic_and", "atomic_or", "atomic_xor", "atomic_cmp_store",
      "atomic_iadd", "atomic_imax", "atomic_imin", "atomic_umax", "atomic_umin", "imm_atomic_alloc",
      "imm_atomic_consume", "imm_atomic_iadd", "imm_atomic_and", "imm_atomic_or", "imm_atomic_xor", "imm_atomic_exch",
      "imm_atomic_cmp_exch", "imm_atomic_imax", "imm_atomic_imin", "imm_atomic_umax", "imm_atomic_umin", "dadd",
      "dmax", "dmin", "dmul", "deq", "dge", "dlt", "dne", "dmov", "dmovc", "dtof", "ftod", "eval_snapped",
      "eval_sample_index", "eval_centroid", "abort", "debug_break", "ddiv", "dfma", "drcp", "msad", "dtoi", "dtou",
      "itod", "utod",
      // hull shader phases
      "hs_decls", "hs_control_point_phase", "hs_fork_phase", "hs_join_phase"};
  return names;
}

// The mnemonic without the modifiers the disassembler writes around it.
std::string mnemonic(const AsmLine& line) {
  std::string base = line.baseOpcode();  // no `_sat`, nothing from the first '(' on
  for (std::string_view suffix : {"_indexable", "_aoffimmi"})
    if (size_t at = base.find(suffix); at != std::string::npos) base.erase(at, suffix.size());
  for (std::string_view suffix : {"_uint", "_nz", "_z"})
    if (base.size() > suffix.size() && base.ends_with(suffix)) {
      base.resize(base.size() - suffix.size());
      break;
    }
  if (base.size() > 5 && base.starts_with("sync")) return "sync";  // sync_g_t, sync_uglobal, ...
  return base;
}

}  // namespace

std::optional<AsmError> findAssemblerError(const AsmText& text) {
  std::set<std::string> declaredBuffers;
  static const std::regex declared(R"(^\s*[cC][bB](\d+)\b)");
  for (const AsmLine& line : text.lines)
    if (line.kind == LineKind::Declaration && line.baseOpcode() == "dcl_constantbuffer" && !line.operands.empty()) {
      std::smatch m;
      if (std::regex_search(line.operands.front().text, m, declared)) declaredBuffers.insert(m[1]);
    }
  static const std::regex read(R"((^|[^A-Za-z0-9_])cb(\d+)\[)");
  for (const AsmLine& line : text.lines) {
    if (line.kind != LineKind::Instruction) continue;
    // NUL padding at the end of a dump (3Dmigoto writes some): not an instruction.
    if (line.text.find_first_not_of(std::string_view("\0 \t\r", 4)) == std::string::npos) continue;
    std::string name = mnemonic(line);
    if (name != "sync" && !instructions().count(name))
      return AsmError{Severity::Error, "", static_cast<int>(line.number),
                      static_cast<int>(line.indent.size() + 1),
                      "'" + line.opcode + "' is no shader model 4 or 5 instruction; the assembler would refuse this dump"};
    for (const Operand& operand : line.operands) {
      std::smatch m;
      if (std::regex_search(operand.text, m, read) && !declaredBuffers.count(m[2]))
        return AsmError{Severity::Error, "", static_cast<int>(line.number), static_cast<int>(operand.column),
                        "cb" + std::string(m[2]) + " is read but no dcl_constantbuffer declares it; the assembler would "
                        "refuse this dump"};
    }
  }
  return std::nullopt;
}

}  // namespace stereoshift::d3dasm
