#include "transpiler/d3dasm/asm_shift.h"

#include "transpiler/d3dasm/asm_halo.h"
#include "transpiler/d3dasm/asm_interpreter.h"
#include "transpiler/d3dasm/asm_unprojection.h"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>

namespace stereoshift::d3dasm {

namespace {

constexpr const char* kWasPrefix = "// stereoshift was: ";
constexpr const char* kBlockBegin = "// ---- stereoshift: ";
constexpr const char* kBlockEnd = "// ---- end stereoshift ----";

// A float literal the way the disassembler writes them (`1.000000`), or with all its digits where
// six decimals would change its value (an epsilon of 1e-7).
std::string floatLiteral(float value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%f", static_cast<double>(value));
  if (std::strtof(buffer, nullptr) != value) std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(value));
  return buffer;
}

// The register number of `operand` when it is `<prefix><digits>` followed by a mask (`o0.xyzw`).
std::optional<uint32_t> registerNumber(std::string_view operand, std::string_view prefix, std::string* mask = nullptr) {
  if (!operand.starts_with(prefix)) return std::nullopt;
  std::string_view rest = operand.substr(prefix.size());
  uint32_t n = 0;
  auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), n);
  if (ec != std::errc() || end == rest.data()) return std::nullopt;
  std::string_view after(end, static_cast<size_t>(rest.data() + rest.size() - end));
  if (!after.empty() && after.front() != '.') return std::nullopt;
  if (mask) *mask = after.empty() ? "xyzw" : std::string(after.substr(1));
  return n;
}

// The w a `mov` writes from a literal source (`l(1.000000)`, `l(0, 0, 0, 1.000000)`), when its
// destination mask `mask` includes w: a scalar literal is every component, a four-component one
// is read per destination component. nullopt when the source is not such a literal.
std::optional<float> literalW(const AsmLine& line, const std::string& mask) {
  if (line.baseOpcode() != "mov" || line.operands.size() != 2) return std::nullopt;
  std::string_view source = line.operands[1].text;
  if (!source.starts_with("l(") || !source.ends_with(")")) return std::nullopt;
  std::vector<std::string> values;
  std::string value;
  for (char c : source.substr(2, source.size() - 3)) {
    if (c == ',') {
      values.push_back(value);
      value.clear();
    } else if (c != ' ') {
      value += c;
    }
  }
  values.push_back(value);
  if (values.size() != 1 && values.size() != 4) return std::nullopt;
  const std::string& w = values.size() == 1 ? values[0] : values[3];
  char* end = nullptr;
  float parsed = std::strtof(w.c_str(), &end);
  if (w.empty() || end != w.c_str() + w.size() || mask.find('w') == std::string::npos) return std::nullopt;
  return parsed;
}

// Whether every write of the position's w is a `mov` of the literal 1 (a 2D shader: HUD, full-screen
// pass, sprite in pixel coordinates): the line of the first such write; nullopt when some write of
// w is anything else or none writes it. A write through a subroutine or a saturating or
// two-result instruction is "anything else".
std::optional<size_t> positionWIsLiteralOne(const AsmText& text, const std::string& out) {
  std::optional<size_t> first;
  const std::optional<uint32_t> position = registerNumber(out, "o");
  for (const AsmLine& line : text.lines) {
    if (line.kind != LineKind::Instruction || registerTokenOffsets(line, out).empty()) continue;
    // An output register is only ever a destination in SM4+: every mention is a write.
    bool writesW = false;
    for (const Operand& operand : line.operands) {
      std::string mask;
      if (registerNumber(operand.text, "o", &mask) == position && mask.find('w') != std::string::npos) writesW = true;
    }
    if (!writesW) continue;
    std::string mask;
    if (line.operands.empty() || registerNumber(line.operands[0].text, "o", &mask) != position) return std::nullopt;
    std::optional<float> w = literalW(line, mask);
    if (!w || *w != 1.0f) return std::nullopt;
    if (!first) first = line.number;
  }
  return first;
}

struct Edits {
  std::map<size_t, std::vector<std::string>> before;  // lines inserted before line k
  std::map<size_t, std::vector<std::string>> after;   // lines inserted after line k
  std::map<size_t, std::string> replaced;             // line k's new text
  std::map<size_t, std::string> why;                  // the marker of a replaced line
};

std::string render(const AsmText& text, const Edits& edits) {
  std::vector<std::string> out;
  auto block = [&](const std::string& indent, const std::string& what, const std::vector<std::string>& lines) {
    out.push_back(indent + kBlockBegin + what + " ----");
    for (const auto& l : lines) out.push_back(indent + l);
    out.push_back(indent + kBlockEnd);
  };
  for (size_t k = 0; k < text.lines.size(); ++k) {
    const AsmLine& line = text.lines[k];
    if (auto it = edits.before.find(k); it != edits.before.end()) {
      // The first entry names the block; the rest are its lines.
      block(line.indent, it->second.front(), {it->second.begin() + 1, it->second.end()});
    }
    if (auto it = edits.replaced.find(k); it != edits.replaced.end()) {
      out.push_back(line.indent + kBlockBegin + edits.why.at(k) + " ----");
      out.push_back(line.indent + kWasPrefix + line.text.substr(line.indent.size()));
      out.push_back(it->second);
      out.push_back(line.indent + kBlockEnd);
    } else {
      out.push_back(line.text);
    }
    if (auto it = edits.after.find(k); it != edits.after.end())
      block(line.indent, it->second.front(), {it->second.begin() + 1, it->second.end()});
  }
  std::string joined;
  for (size_t k = 0; k < out.size(); ++k) {
    joined += out[k];
    if (k + 1 < out.size() || text.endsWithNewline) joined += text.newline;
  }
  return joined;
}

std::string countWord(size_t n) {
  static const char* const words[] = {"no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine"};
  return n < 10 ? words[n] : std::to_string(n);
}

bool isEmit(const std::string& base) {
  return base == "emit" || base == "emit_stream" || base == "emitThenCut" || base == "emitThenCut_stream";
}
bool isReturn(const std::string& base) { return base == "ret" || base == "retc_nz" || base == "retc_z"; }

// The declarations the edit reads: the position output, the temporaries, t125, where to declare.
struct Declarations {
  std::optional<uint32_t> position;
  std::string positionMask;
  size_t positionLineNumber = 0, positionColumn = 0;  // where the position is declared
  std::optional<size_t> tempsLine, stereoParamsLine;
  uint32_t temps = 0;
  size_t lastResourceDeclaration = 0, lastDeclaration = 0;
};

bool readDeclarations(const AsmText& text, Declarations* d, AsmError* error) {
  d->lastResourceDeclaration = d->lastDeclaration = text.modelLine;
  for (size_t k = 0; k < text.lines.size(); ++k) {
    const AsmLine& line = text.lines[k];
    if (line.kind != LineKind::Declaration) continue;
    d->lastDeclaration = line.lastLine;
    const std::string base = line.baseOpcode();
    if (base == "dcl_output_siv" && line.operands.size() == 2 && line.operands[1].text == "position") {
      std::string mask;
      auto n = registerNumber(line.operands[0].text, "o", &mask);
      if (!n) {
        *error = errorAt(line.number, line.operands[0].column, "the position output '" + line.operands[0].text + "' is not an o register");
        return false;
      }
      if (d->position && *d->position != *n) {
        *error = errorAt(line.number, line.operands[0].column,
                         "a second position output (o" + std::to_string(*d->position) + " and o" + std::to_string(*n) +
                             "): the assembly route shifts one");
        return false;
      }
      d->position = n;
      d->positionMask = mask;
      d->positionLineNumber = line.number;
      d->positionColumn = line.operands[0].column;
    } else if (base == "dcl_temps" && line.operands.size() == 1) {
      uint32_t n = 0;
      const std::string& count = line.operands[0].text;
      auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
      if (ec != std::errc() || end != count.data() + count.size()) {
        *error = errorAt(line.number, line.operands[0].column, "dcl_temps takes a count, not '" + count + "'");
        return false;
      }
      d->temps = n;
      d->tempsLine = k;
    } else if (base.starts_with("dcl_resource") || base == "dcl_sampler" || base == "dcl_constantbuffer" ||
               base == "dcl_immediateConstantBuffer" || base == "dcl_globalFlags") {
      d->lastResourceDeclaration = line.lastLine;
      if (base.starts_with("dcl_resource") && !line.operands.empty()) {
        const Operand& reg = line.operands.back();
        if (reg.text == "t125" || reg.text.starts_with("t125.")) {
          if (line.opcode != "dcl_resource_texture2d" || line.operands.size() != 2 ||
              line.operands[0].text != "(float,float,float,float)") {
            *error = errorAt(line.number, reg.column,
                             "t125 is declared as another resource ('" + line.text.substr(line.indent.size()) +
                                 "'): 3Dmigoto's StereoParams texture lives there");
            return false;
          }
          d->stereoParamsLine = k;
        }
      }
    }
  }
  if (!d->position) return true;
  for (const AsmLine& line : text.lines) {
    if (line.kind != LineKind::Declaration || line.baseOpcode() != "dcl_indexrange" || line.operands.size() != 2) continue;
    auto first = registerNumber(line.operands[0].text, "o");
    uint32_t count = 0;
    const std::string& n = line.operands[1].text;
    std::from_chars(n.data(), n.data() + n.size(), count);
    if (first && *first <= *d->position && *d->position < *first + count) {
      *error = errorAt(line.number, line.operands[0].column, "the position output o" + std::to_string(*d->position) +
                                                                 " is in an indexed output range: its writes cannot be redirected");
      return false;
    }
  }
  return true;
}

// 3Dmigoto's StereoParams texel 0 into `rS` (x: separation with the eye's sign, y: convergence);
// SM4.x has no ld_indexable.
std::string stereoParamsLoad(const std::string& rS, bool sm5) {
  return (sm5 ? "ld_indexable(texture2d)(float,float,float,float) " : "ld ") + rS + ".xyzw, l(0, 0, 0, 0), t125.xyzw";
}

// The block before each return or emit: read StereoParams into rS, shift rP.x into rS.x where the
// cutoff lets it, write the position out.
// With `halos`, each redirected output register (its temporary, its declared mask) is written out
// with its moved lanes: a copy of x takes the shifted x where x is shifted (`movc` on the same
// condition), another lane its value plus a times the shift. `shiftPosition` false
// (--corrections-only: the driver shifts the position) writes the position out as it is.
struct HaloOutput {
  std::string out, temp, mask;
  std::vector<AsmMovedLane> lanes;
};

std::vector<std::string> shiftBlock(const std::string& out, const std::string& mask, const std::string& rP,
                                    const std::string& rS, bool sm5, const ShiftSpec& spec,
                                    const std::vector<HaloOutput>& halos = {}, bool shiftPosition = true) {
  std::string lanes;
  for (const HaloOutput& halo : halos)
    for (const AsmMovedLane& lane : halo.lanes) lanes += std::string(lanes.empty() ? "" : ", ") + halo.out + "." + "xyzw"[lane.lane];
  std::vector<std::string> shift = {
      !shiftPosition ? "what moves with " + out + ".x (" + lanes + "; the driver shifts " + out + ": --corrections-only)"
      : halos.empty() ? "clip-space shift of " + out + " (3Dmigoto StereoParams, t125)"
                      : "clip-space shift of " + out + " and what moves with its x (" + lanes + ") (3Dmigoto StereoParams, t125)",
      stereoParamsLoad(rS, sm5),
      "add " + rS + ".w, " + rP + ".w, -" + rS + ".y",
      "mad " + rS + ".w, " + rS + ".x, " + rS + ".w, " + rP + ".x",
      "ne " + rS + ".x, " + rS + ".x, l(0.000000)",
  };
  if (const CutoffMode cutoff = normalisedCutoff(spec.cutoff, spec.epsilon); cutoff != CutoffMode::None) {
    if (cutoff == CutoffMode::Epsilon) {
      shift.push_back("add " + rS + ".y, " + rP + ".w, l(-1.000000)");
      shift.push_back("lt " + rS + ".y, l(" + floatLiteral(spec.epsilon) + "), |" + rS + ".y|");
    } else {
      shift.push_back("ne " + rS + ".y, " + rP + ".w, l(1.000000)");
    }
    shift.push_back("and " + rS + ".x, " + rS + ".x, " + rS + ".y");
    shift.push_back("lt " + rS + ".y, |" + rP + ".w|, l(" + floatLiteral(FLT_MAX) + ")");
    shift.push_back("and " + rS + ".x, " + rS + ".x, " + rS + ".y");
  }
  // rS.x: whether x is shifted; rS.w: the shifted x; rS.y is free.
  for (const HaloOutput& halo : halos) {
    shift.push_back("mov " + halo.out + "." + halo.mask + ", " + halo.temp + "." + halo.mask);
    for (const AsmMovedLane& lane : halo.lanes) {
      const std::string at = halo.temp + "." + "xyzw"[lane.lane], to = halo.out + "." + "xyzw"[lane.lane];
      if (lane.copy) {
        shift.push_back("movc " + to + ", " + rS + ".x, " + rS + ".w, " + at);
        continue;
      }
      shift.push_back("add " + rS + ".y, " + rS + ".w, -" + rP + ".x");
      shift.push_back("mad " + rS + ".y, " + rS + ".y, l(" + floatLiteral(lane.coefficient) + "), " + at);
      shift.push_back("movc " + to + ", " + rS + ".x, " + rS + ".y, " + at);
    }
  }
  if (!shiftPosition) {
    shift.push_back("mov " + out + "." + mask + ", " + rP + "." + mask);
    return shift;
  }
  shift.push_back("movc " + rS + ".x, " + rS + ".x, " + rS + ".w, " + rP + ".x");
  shift.push_back("mov " + out + "." + mask + ", " + rP + "." + mask);
  shift.push_back("mov " + out + ".x, " + rS + ".x");
  return shift;
}

// `count` more temporaries (`why` says what for) and t125 declared unless the dump has it.
void declareScratch(const AsmText& text, const Declarations& d, uint32_t count, const std::string& why, Edits& edits,
                    AsmShiftResult& result) {
  if (d.tempsLine) {
    edits.replaced[*d.tempsLine] = text.lines[*d.tempsLine].indent + "dcl_temps " + std::to_string(d.temps + count);
    edits.why[*d.tempsLine] = why;
  } else {
    edits.after[d.lastDeclaration].push_back(why);
    edits.after[d.lastDeclaration].push_back("dcl_temps " + std::to_string(count));
  }
  if (!d.stereoParamsLine) {
    std::vector<std::string>& declare = edits.after[d.lastResourceDeclaration];
    if (!declare.empty()) {
      // The same line ends the resources and the declarations: one block with both.
      declare.front() = "3Dmigoto's StereoParams texture; " + declare.front();
      declare.insert(declare.begin() + 1, "dcl_resource_texture2d (float,float,float,float) t125");
    } else {
      declare = {"3Dmigoto's StereoParams texture", "dcl_resource_texture2d (float,float,float,float) t125"};
    }
    result.declaredStereoParams = true;
  }
}

// The line of an instruction that reads t125 (a stereo fix already), or 0.
size_t readsStereoParams(const AsmText& text) {
  for (const AsmLine& line : text.lines)
    if (line.kind == LineKind::Instruction && !registerTokenOffsets(line, "t125").empty()) return line.number;
  return 0;
}

// d *= h, the screen coordinate's half-width from the matrix (AsmUnprojection::scaleFromTheMatrix;
// docs/3dmigoto.md): with x, z, t InvM's columns of the coordinate, the depth and the constant,
// h = -dot(t.xyz z.w - z.xyz t.w, x.xyz) / (dot(x.xyz, x.xyz) z.w), taken where it is over 0.25 (a
// UV or a pixel position: its half-width), 1 otherwise (NDC). rT holds the parts.
void appendScreenScale(const AsmUnprojection& u, const std::string& rS, const std::string& rT,
                       std::vector<std::string>& block) {
  auto negated = [](const std::string& operand) { return operand[0] == '-' ? operand.substr(1) : "-" + operand; };
  std::array<std::string, 3> x;
  for (size_t i = 0; i < 3; ++i) x[i] = (u.columnScale[i] < 0 ? "-" : "") + u.column[i];
  const char lanes[] = "xyz";
  if (u.scaledByDepth) {  // M (c z, c' z, z, 1): h = -dot(z.xyz, x.xyz) / dot(x.xyz, x.xyz)
    block.push_back("mul " + rT + ".x, " + u.columnZ[0] + ", " + x[0]);
    block.push_back("mad " + rT + ".x, " + u.columnZ[1] + ", " + x[1] + ", " + rT + ".x");
    block.push_back("mad " + rT + ".x, " + u.columnZ[2] + ", " + x[2] + ", " + rT + ".x");
  } else {
    for (size_t i = 0; i < 3; ++i) {
      const std::string a = rT + "." + lanes[i];
      block.push_back("mul " + a + ", " + u.translation[i] + ", " + u.columnZ[3]);
      block.push_back("mad " + a + ", " + negated(u.columnZ[i]) + ", " + u.translation[3] + ", " + a);
    }
    block.push_back("mul " + rT + ".x, " + rT + ".x, " + x[0]);
    block.push_back("mad " + rT + ".x, " + rT + ".y, " + x[1] + ", " + rT + ".x");
    block.push_back("mad " + rT + ".x, " + rT + ".z, " + x[2] + ", " + rT + ".x");
  }
  block.push_back("mul " + rT + ".y, " + x[0] + ", " + x[0]);
  block.push_back("mad " + rT + ".y, " + x[1] + ", " + x[1] + ", " + rT + ".y");
  block.push_back("mad " + rT + ".y, " + x[2] + ", " + x[2] + ", " + rT + ".y");
  if (!u.scaledByDepth) block.push_back("mul " + rT + ".y, " + rT + ".y, " + u.columnZ[3]);
  block.push_back("div " + rT + ".x, -" + rT + ".x, " + rT + ".y");
  block.push_back("lt " + rT + ".y, l(0.250000), " + rT + ".x");
  block.push_back("movc " + rT + ".x, " + rT + ".y, " + rT + ".x, l(1.000000)");
  block.push_back("mul " + rS + ".w, " + rS + ".w, " + rT + ".x");
}

// The correction of one position rebuild (see asm_shift.h), after the instruction completing q.
std::vector<std::string> correctionBlock(const AsmUnprojection& u, const std::string& rS, const std::string& rT,
                                         bool sm5) {
  const std::string lines = u.firstLineNumber == u.lastLineNumber
                                ? "line " + std::to_string(u.lastLineNumber)
                                : "lines " + std::to_string(u.firstLineNumber) + "-" + std::to_string(u.lastLineNumber);
  std::vector<std::string> block = {
      "this eye's position rebuild (" + lines + (u.scaledByDepth && u.scaleFromTheMatrix
                                                     ? ": q = M * (screen * depth, depth, 1), the screen's scale from M, over "
                                : u.scaledByDepth ? ": q = M * (ndc * depth, depth, 1) over "
                                : u.uvOfTheDepthTexture ? ": q = InvM * (uv, depth, 1) over "
                                : u.scaleFromTheMatrix  ? ": q = M * (screen, depth, 1), the screen's scale from M, over "
                                                        : ": q = InvM * (ndc, depth, 1) over ") +
          u.rows + ")",
      stereoParamsLoad(rS, sm5),
  };
  if (u.scaledByDepth) {
    // d = s.x * (|z| - s.y) * sign(z)
    const std::string& z = u.depthRegister;
    block.push_back("add " + rS + ".w, |" + z + "|, -" + rS + ".y");
    block.push_back("mul " + rS + ".w, " + rS + ".w, " + rS + ".x");
    block.push_back("lt " + rS + ".z, " + z + ", l(0.000000)");
    block.push_back("movc " + rS + ".w, " + rS + ".z, -" + rS + ".w, " + rS + ".w");
  } else {
    // d = s.x * (1 - s.y * q.w)
    block.push_back("mad " + rS + ".w, -" + rS + ".y, " + u.q[3] + ", l(1.000000)");
    block.push_back("mul " + rS + ".w, " + rS + ".w, " + rS + ".x");
  }
  if (u.scaleFromTheMatrix) appendScreenScale(u, rS, rT, block);
  for (size_t i = 0; i < 4; ++i) {
    if (u.q[i].empty()) continue;  // the w of a point the shader never computes
    if (u.columnScale[i] == 1.0f || u.columnScale[i] == -1.0f) {
      const char* sign = u.columnScale[i] == 1.0f ? "-" : "";
      block.push_back("mad " + u.q[i] + ", " + sign + u.column[i] + ", " + rS + ".w, " + u.q[i]);
    } else {
      block.push_back("mul " + rS + ".z, " + u.column[i] + ", l(" + floatLiteral(u.columnScale[i]) + ")");
      block.push_back("mad " + u.q[i] + ", -" + rS + ".z, " + rS + ".w, " + u.q[i]);
    }
  }
  return block;
}

// The correction of one view ray (see asm_unprojection.h), after the instruction computing x.
std::vector<std::string> rayBlock(const AsmViewRay& r, const std::string& rS, bool sm5) {
  const std::string scale = floatLiteral(std::abs(r.scale));
  std::vector<std::string> block = {
      "this eye's view-space x (line " + std::to_string(r.lineNumber) + ": x = ndc.x * depth * " +
          (r.divides ? "(1 / " + r.element + ")" : r.element) + ")",
      stereoParamsLoad(rS, sm5),
      "add " + rS + ".w, |" + r.depthRegister + "|, -" + rS + ".y",
      "mul " + rS + ".w, " + rS + ".w, " + rS + ".x",
      std::string(r.divides ? "div " : "mul ") + rS + ".w, " + rS + ".w, |" + r.element + "|",
  };
  if (std::abs(r.scale) != 1.0f) block.push_back("mul " + rS + ".w, " + rS + ".w, l(" + scale + ")");
  block.push_back("add " + r.x + ", " + r.x + ", -" + rS + ".w");
  return block;
}

// This eye's camera for a view vector to a rebuilt position (see asm_unprojection.h), after the
// instruction computing it: rT.xyz the camera InvM shows, each compared with c (within 1e-4 of
// |camera| + 1), and v += s.x * s.y * InvM[column of x] where all three agree (InvM's column the
// matrix's times the half-width in rS.w where the matrix takes a screen coordinate of unknown scale).
std::vector<std::string> cameraBlock(const AsmUnprojection& u, const AsmUnprojection::Camera& c, const std::string& rS,
                                     const std::string& rT, bool sm5) {
  std::vector<std::string> block = {
      "this eye's camera (line " + std::to_string(c.lineNumber) +
          (c.fromCamera ? ": v = position - camera" : ": v = camera - position") + ", the camera the position's matrix shows)",
      stereoParamsLoad(rS, sm5),
  };
  if (u.scaleFromTheMatrix) {  // rS.w = h, the screen coordinate's half-width (InvM's column is M's times it)
    block.push_back("mov " + rS + ".w, l(1.000000)");
    appendScreenScale(u, rS, rT, block);
  }
  const char lanes[] = "xyz";
  for (int i = 0; i < 3; ++i) {
    const std::string t = rT + "." + lanes[i];
    block.push_back("div " + t + ", " + c.centre[i] + ", " + c.centre[3]);
    block.push_back("add " + rT + ".w, " + c.camera[i] + ", -" + t);
    block.push_back("mad " + rS + ".z, |" + t + "|, l(0.000100), l(0.000100)");
    block.push_back("ge " + t + ", " + rS + ".z, |" + rT + ".w|");
  }
  block.push_back("and " + rT + ".x, " + rT + ".x, " + rT + ".y");
  block.push_back("and " + rT + ".x, " + rT + ".x, " + rT + ".z");
  block.push_back("mul " + rS + ".z, " + rS + ".x, " + rS + ".y");
  if (u.scaleFromTheMatrix) block.push_back("mul " + rS + ".z, " + rS + ".z, " + rS + ".w");  // times h
  for (int i = 0; i < 3; ++i) {
    // c moves by +s.x*s.y*InvM[column of x]: c - p by as much, p - c by minus as much. InvM's column
    // is the element times its scale (half of it for a matrix from UV space).
    std::string factor = rS + ".z";
    if (u.columnScale[i] != 1.0f) {
      block.push_back("mul " + rT + ".w, " + rS + ".z, l(" + floatLiteral(u.columnScale[i]) + ")");
      factor = rT + ".w";
    }
    block.push_back("mad " + rT + ".w, " + (c.fromCamera ? "-" : "") + factor + ", " + u.column[i] + ", " + c.v[i]);
    block.push_back("movc " + c.v[i] + ", " + rT + ".x, " + rT + ".w, " + c.v[i]);
  }
  return block;
}

// A pixel shader: its position rebuilds corrected, or the text as it is with why.
AsmShiftResult correctPixelShader(const std::string& source, const AsmText& text, AsmShiftResult result) {
  auto unchanged = [&](std::string why) {
    result.ok = true;
    result.output = source;
    result.whyUnchanged = std::move(why);
    return result;
  };
  // A pixel shader was always copied before it could be corrected: a declaration the edit could not
  // work with (t125 declared as another resource) leaves it copied, with the reason, not refused.
  Declarations d;
  AsmError declarationError;
  if (!readDeclarations(text, &d, &declarationError))
    return unchanged("not corrected (line " + std::to_string(declarationError.line) + ": " + declarationError.message + ")");
  if (size_t line = readsStereoParams(text)) {
    result.alreadyStereo = true;
    return unchanged("line " + std::to_string(line) + " reads 3Dmigoto's StereoParams (t125): a stereo fix already, left as it is");
  }
  AsmError why;
  std::unique_ptr<Program> program = Program::decode(text, &why, DecodeFor::Analysis);
  if (!program)
    return unchanged("the pixel shader was not analysed (line " + std::to_string(why.line) + ": " + why.message +
                     "): no correction looked for");
  const AsmUnprojections all = findAsmUnprojections(text, *program);
  const std::vector<AsmUnprojection>& found = all.found;
  result.leftAlone = all.leftAlone;
  if (found.empty() && all.rays.empty() && !all.leftAlone.empty()) {
    std::string why;
    for (const auto& left : all.leftAlone) why += (why.empty() ? "" : "; ") + left;
    return unchanged(text.model.text + ": left for a person: " + why);
  }
  if (found.empty() && all.rays.empty())
    return unchanged(text.model.text + ": no position rebuilt from depth through constant-buffer rows, nothing to correct");
  const std::string rS = "r" + std::to_string(d.temps), rT = "r" + std::to_string(d.temps + 1);
  result.scratchTemp = rS;
  Edits edits;
  bool cameras = false, scaled = false;
  for (const AsmUnprojection& u : found) {
    std::vector<std::string>& after = edits.after[u.afterLine];
    if (!after.empty()) continue;  // two rebuilds completed by one instruction: corrected once
    after = correctionBlock(u, rS, rT, text.model.major >= 5);
    scaled |= u.scaleFromTheMatrix;  // its half-width's parts in rT
    std::string fix = "q -= (";
    for (size_t i = 0; i < 4; ++i) fix += (i ? ", " : "") + (u.q[i].empty() ? std::string("-") : u.column[i]);
    fix += std::string(") * ") +
           (u.scaledByDepth && u.scaleFromTheMatrix
                ? "s.x*(|z| - s.y)*sign(z) * h (h the screen coordinate's half-width the matrix shows), z in " +
                      u.depthRegister + ","
            : u.scaledByDepth      ? "s.x*(|z| - s.y)*sign(z), z in " + u.depthRegister + ","
            : u.scaleFromTheMatrix ? "s.x*(1 - s.y*q.w) * h (h the screen coordinate's half-width the matrix shows)"
                                   : "s.x*(1 - s.y*q.w)") +
           " after line " + std::to_string(u.lastLineNumber) +
           (u.q[3].empty() ? " (the point has no w: an affine map)" : ", before the divide");
    result.corrections.push_back({std::string(u.scaledByDepth ? "position rebuilt through a screen-to-world matrix (ndc * depth, depth, 1) "
                                                                "held as four constant-buffer "
                                                              : "position rebuilt through a matrix held as four constant-buffer ") +
                                      u.storage,
                                  u.rows, u.depth, u.ndc, fix, u.firstLineNumber, u.lastLineNumber});
    for (const auto& c : u.cameras) {
      std::vector<std::string>& at = edits.after[c.afterLine];
      if (!at.empty()) continue;
      at = cameraBlock(u, c, rS, rT, text.model.major >= 5);
      cameras = true;
      result.corrections.push_back({c.fromCamera ? "view vector rebuilt position - camera (reflections, fog rays)"
                                                  : "view vector camera - rebuilt position (specular, Fresnel, reflections)",
                                    u.rows, u.depth, u.ndc,
                                    std::string(c.fromCamera ? "v - " : "v + ") + "s.x*s.y*(" + u.column[0] + ", " + u.column[1] + ", " + u.column[2] + ") after line " +
                                        std::to_string(c.lineNumber) + ", where " + c.camera[0].substr(0, c.camera[0].rfind('.')) +
                                        " is the camera the matrix shows (checked at run time)",
                                    c.lineNumber, c.lineNumber});
    }
  }
  for (const AsmViewRay& r : all.rays) {
    std::vector<std::string>& after = edits.after[r.afterLine];
    if (!after.empty()) continue;
    after = rayBlock(r, rS, text.model.major >= 5);
    const std::string k = r.divides ? "1 / " + r.element : r.element;
    result.corrections.push_back({"view-space position rebuilt from depth one component at a time (view ray)",
                                  "", r.depth, r.ndc,
                                  "x - s.x*(|depth| - s.y)*|k|, k = " + k + ", depth in " + r.depthRegister + ", after line " +
                                      std::to_string(r.lineNumber),
                                  r.lineNumber, r.lineNumber});
  }
  declareScratch(text, d, cameras || scaled ? 2 : 1,
                 cameras ? "two temporaries for this eye's position rebuild and camera (" + rS + ", " + rT + ")"
                 : scaled ? "two temporaries for this eye's position rebuild and its screen's scale (" + rS + ", " + rT + ")"
                          : "a temporary for this eye's position rebuild (" + rS + ")",
                 edits, result);
  result.sites = static_cast<int>(result.corrections.size());
  result.output = render(text, edits);
  result.ok = true;
  return result;
}

// The halos (asm_halo.h): output lanes that move with x, grouped by register, each register given
// a temporary of its own after the shift's rP and rS.
std::vector<HaloOutput> haloOutputs(const AsmText& text, const Declarations& d) {
  std::vector<HaloOutput> halos;
  AsmError why;
  std::unique_ptr<Program> program = Program::decode(text, &why, DecodeFor::Analysis);
  if (!program) return halos;
  for (const AsmMovedLane& lane : findAsmMovedLanes(*program)) {
    const std::string o = "o" + std::to_string(lane.reg);
    if (halos.empty() || halos.back().out != o) {
      std::string mask;
      for (uint32_t c = 0; c < 4; ++c)
        if (program->outputMasks().at(lane.reg) & (1u << c)) mask += "xyzw"[c];
      halos.push_back({o, "r" + std::to_string(d.temps + 2 + halos.size()), mask, {}});
    }
    halos.back().lanes.push_back(lane);
  }
  return halos;
}

// Line k's writes of the redirected output registers (`redirected`: output, its temporary; the
// position first) replaced by their temporaries, as a marked edit; how many writes of the position
// it had.
int redirectWrites(const AsmLine& line, size_t k, const std::vector<std::pair<std::string, std::string>>& redirected,
                   Edits& edits) {
  std::vector<std::pair<size_t, size_t>> offsets;  // offset, index in `redirected`
  for (size_t r = 0; r < redirected.size(); ++r)
    for (size_t offset : registerTokenOffsets(line, redirected[r].first)) offsets.push_back({offset, r});
  if (offsets.empty()) return 0;
  std::sort(offsets.begin(), offsets.end());
  std::string edited = line.text, why;
  int positionWrites = 0;
  for (auto it = offsets.rbegin(); it != offsets.rend(); ++it)
    edited.replace(it->first, redirected[it->second].first.size(), redirected[it->second].second);
  for (const auto& [offset, r] : offsets) {
    if (r == 0) ++positionWrites;
    const std::string what = r == 0 ? "the position is written to " + redirected[0].second
                                    : redirected[r].first + " is written to " + redirected[r].second;
    if (why.find(what) == std::string::npos) why += (why.empty() ? "" : "; ") + what;
  }
  edits.replaced[k] = edited;
  edits.why[k] = why + " (outputs cannot be read back)";
  return positionWrites;
}

}  // namespace

AsmShiftResult shiftAssembly(const std::string& source, const ShiftSpec& spec, bool pixelCorrections, bool shiftPosition) {
  AsmShiftResult result;
  Result<AsmText> parsed = parseAssembly(source);
  if (!parsed) {
    result.error = parsed.error();
    return result;
  }
  const AsmText& text = *parsed;
  result.model = text.model.text;
  result.stage = stageOfShaderModel(text.model);
  result.modelLine = text.lines[text.modelLine].number;
  auto unchanged = [&](std::string why) {
    result.ok = true;
    result.output = source;
    result.whyUnchanged = std::move(why);
    return result;
  };
  const std::optional<Stage> stage = result.stage;
  if (stage == Stage::Fragment && text.model.major >= 4 && pixelCorrections)
    return correctPixelShader(source, text, std::move(result));
  if (stage != Stage::Vertex && stage != Stage::TessEvaluation && stage != Stage::Geometry)
    return unchanged(text.model.text + ": only vertex, domain and geometry shaders write the clip position");
  // A D3D9 vertex shader copied as it is would be a mono drop-in that looks converted: an error.
  if (text.model.major < 4) {
    result.error = errorAt(text.lines[text.modelLine].number, text.lines[text.modelLine].indent.size() + 1,
                           text.model.text + ": shader model " + std::to_string(text.model.major) +
                               " (D3D9) assembly is not edited; the assembly route reads SM4 and SM5");
    return result;
  }

  Declarations d;
  if (!readDeclarations(text, &d, &result.error)) return result;
  if (!d.position) return unchanged("no position output (dcl_output_siv oN, position): nothing to shift");
  const std::string out = "o" + std::to_string(*d.position);
  // A shader that reads StereoParams already is a stereo fix (3Dmigoto users edit the assembly by
  // hand; stereoshift's own output reads it too): shifting it again would shift twice.
  if (size_t line = readsStereoParams(text)) {
    result.alreadyStereo = true;
    return unchanged("line " + std::to_string(line) + " reads 3Dmigoto's StereoParams (t125): a stereo fix already, left as it is");
  }
  // A position whose w is the literal 1 at every write is a proven 2D shader: the shift's cutoff would
  // keep every vertex mono, so the dump is copied as it is, with the reason (the SPIR-V analyses
  // classify the same shaders "2d-constant-w").
  if (auto line = positionWIsLiteralOne(text, out))
    return unchanged("the position's w is written only as the literal 1 (line " + std::to_string(*line) + ", " + out +
                     ".w): a 2D shader, which the shift's cutoff keeps mono, copied as it is");
  const std::string rP = "r" + std::to_string(d.temps), rS = "r" + std::to_string(d.temps + 1);
  result.positionRegister = out;
  result.positionTemp = rP;
  result.scratchTemp = rS;

  const std::vector<HaloOutput> halos = stage == Stage::Geometry ? std::vector<HaloOutput>{} : haloOutputs(text, d);
  for (const HaloOutput& halo : halos) result.movedLanes.insert(result.movedLanes.end(), halo.lanes.begin(), halo.lanes.end());
  if (!shiftPosition && halos.empty())
    return unchanged("--corrections-only: the position is left to the driver's shift");  // and nothing moves with x

  Edits edits;
  // The writes of the position into rP, of each halo register into its temporary. An output
  // register is never a source in SM4+, so every mention in an instruction is a write (mov, mad,
  // ..., and two-result instructions alike).
  std::vector<std::pair<std::string, std::string>> redirected = {{out, rP}};
  for (const HaloOutput& halo : halos) redirected.push_back({halo.out, halo.temp});
  bool inSubroutine = false;
  std::vector<size_t> sites;
  for (size_t k = 0; k < text.lines.size(); ++k) {
    const AsmLine& line = text.lines[k];
    if (line.kind != LineKind::Instruction) continue;
    const std::string base = line.baseOpcode();
    if (base == "label") inSubroutine = true;
    result.redirectedWrites += redirectWrites(line, k, redirected, edits);
    if (stage == Stage::Geometry ? isEmit(base) : (isReturn(base) && !inSubroutine)) sites.push_back(k);
  }
  if (result.redirectedWrites == 0) {
    result.error = errorAt(d.positionLineNumber, d.positionColumn,
                           "the position output " + out + " is declared but no instruction writes it");
    return result;
  }
  if (sites.empty()) {
    result.error = errorAt(0, 0, stage == Stage::Geometry ? "no emit instruction: the geometry shader emits no vertex"
                                                          : "no ret instruction in the main program");
    return result;
  }

  const std::vector<std::string> shift =
      shiftBlock(out, d.positionMask, rP, rS, text.model.major >= 5, spec, halos, shiftPosition);
  for (size_t k : sites) edits.before[k] = shift;
  result.sites = static_cast<int>(sites.size());

  // Two more temporaries (and one per halo register); t125 declared unless the dump has it.
  std::string temporaries = rP + ", " + rS;
  for (const HaloOutput& halo : halos) temporaries += ", " + halo.temp;
  declareScratch(text, d, static_cast<uint32_t>(2 + halos.size()),
                 countWord(2 + halos.size()) + " temporaries for the shift (" + temporaries + ")", edits, result);
  result.positionShifted = shiftPosition;
  result.output = render(text, edits);
  result.ok = true;
  result.shifted = true;
  return result;
}

std::string undoAssemblyEdits(const std::string& text) {
  std::string out;
  bool inBlock = false;
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    size_t next = end == std::string::npos ? text.size() : end + 1;
    std::string line = text.substr(at, next - at);
    at = next;
    std::string_view code = line;
    while (!code.empty() && (code.front() == ' ' || code.front() == '\t')) code.remove_prefix(1);
    if (code.starts_with(kBlockBegin)) {
      inBlock = true;
      continue;
    }
    if (code.starts_with(kBlockEnd)) {
      inBlock = false;
      continue;
    }
    if (!inBlock) {
      out += line;
    } else if (code.starts_with(kWasPrefix)) {
      size_t indent = line.size() - code.size();
      out += line.substr(0, indent) + std::string(code.substr(std::string_view(kWasPrefix).size()));
    }
  }
  return out;
}

}  // namespace stereoshift::d3dasm
