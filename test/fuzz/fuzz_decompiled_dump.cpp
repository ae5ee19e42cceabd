// libFuzzer target: this turns an arbitrary byte string into a shader written the way 3Dmigoto's
// decompiler writes game shaders, then into one call of stereoshift::transpile on it, so the crash
// classes of real dumps (a construct every decompiled dump uses that a third-party library cannot
// take) are found here rather than in a game. Byte-level fuzzing of HLSL rarely gets past the
// parser; this target spends its inputs on programs the parser accepts.
//
// The bytes are read one at a time as choices (0 once they run out, which ends every list): the
// stage (vertex or pixel), the eye source, the cbuffers (numbered `cbN[k]` arrays and named matrices,
// row- or column-major, arrays of them), then statements on the decompiler's registers
// (`r1.xyz = ...;`): swizzles of every width, cbuffer rows, matrix swizzles of one or several
// components (`World._m00_m10_m20_m30`), `dot`, `mad` chains, `mul` and `transpose`, `cmp(a < b)`,
// `asuint`/`asfloat` and integer casts, ternaries, `Load`/`SampleLevel`/`Sample`, intrinsics, and
// `if` blocks, structured-buffer and immediate-constant-buffer reads, register-indexed cbuffer rows,
// the bitfield inserts through `bitmask`, `sincos`, `GetDimensions` through `uiDest`, `f16tof32`,
// `ddx_coarse` (pixel); then the position (vertex) or the colour (pixel) from them. The file is named
// `<16 hex>-vs_replace.txt` / `-ps_replace.txt`, with 3Dmigoto's header and declarations, as in
// ShaderFixes/. A crash, a sanitizer report or a broken API promise is a finding.
#include "transpiler/stereoshift.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace stereoshift;

class Choices {
 public:
  Choices(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  // One of `n` (n > 0).
  unsigned pick(unsigned n) { return byte() % n; }
  bool exhausted() const { return at_ >= size_; }

 private:
  const uint8_t* data_;
  size_t size_, at_ = 0;
};

constexpr const char* kComponents = "xyzw";

struct Matrix {
  std::string name;
  int rows, columns;
  int count;  // 1: not an array
};

class DumpWriter {
 public:
  DumpWriter(Choices& c, bool pixel) : c_(c), pixel_(pixel) {}

  std::string write() {
    std::string out = "// ---- Created with 3Dmigoto v1.3.16 on Sun Dec 06 20:00:00 2026\n";
    cbufferRows_ = 4 + static_cast<int>(c_.pick(60));
    out += "cbuffer cb0 : register(b0)\n{\n  float4 cb0[" + std::to_string(cbufferRows_) + "];\n}\n\n";
    // Named matrices in a cbuffer of their own, with packoffsets that do not overlap.
    static const char* const names[] = {"ViewProj", "World", "WorldView", "Projection", "Bones"};
    out += "cbuffer Frame : register(b1)\n{\n";
    int offset = 0;
    unsigned matrices = 1 + c_.pick(4);
    for (unsigned m = 0; m < matrices; ++m) {
      Matrix mat{names[m], 3 + static_cast<int>(c_.pick(2)), 3 + static_cast<int>(c_.pick(2)),
                 m == 3 && c_.pick(2) ? 2 + static_cast<int>(c_.pick(6)) : 1};
      if (m == 0) mat.rows = mat.columns = 4;
      const bool rowMajor = c_.pick(2);
      const int registers = (rowMajor ? mat.rows : mat.columns) * mat.count;
      out += std::string("  ") + (rowMajor ? "row_major " : "") + "float" + std::to_string(mat.rows) + "x" +
             std::to_string(mat.columns) + " " + mat.name + (mat.count > 1 ? "[" + std::to_string(mat.count) + "]" : "") +
             " : packoffset(c" + std::to_string(offset) + ");\n";
      offset += registers;
      matrices_.push_back(mat);
    }
    out += "  float4 CameraPosition : packoffset(c" + std::to_string(offset) + ");\n}\n\n";
    out += "\n\n\n// 3Dmigoto declarations\n#define cmp -\nTexture1D<float4> IniParams : register(t120);\n"
           "Texture2D<float4> StereoParams : register(t125);\n\nSamplerState s0_s : register(s0);\n"
           "Texture2D<float4> t0 : register(t0);\n";
    // A structured buffer and an immediate constant buffer, as the decompiler declares them.
    out += "struct t1_t {\n  float val[16];\n};\nStructuredBuffer<t1_t> t1 : register(t1);\n\n";
    out += "static const float4 icb[] = { { 1.000000, 0, 0, 0},\n                              { 0, 1.000000, 0, 0},\n"
           "                              { 0, 0, 1.000000, 0},\n                              { 0, 0, 0, 1.000000} };\n";
    out += "\n\nvoid main(\n";
    if (pixel_) {
      out += "  float4 v0 : SV_POSITION0,\n  float4 v1 : TEXCOORD0,\n  float3 v2 : TEXCOORD1,\n"
             "  out float4 o0 : SV_Target0)\n";
    } else {
      out += "  float4 v0 : POSITION0,\n  float4 v1 : TEXCOORD0,\n  float3 v2 : NORMAL0,\n"
             "  out float4 o0 : SV_POSITION0,\n  out float4 o1 : TEXCOORD0)\n";
    }
    out += "{\n  float4 r0,r1,r2,r3,r4,r5;\n  uint4 bitmask, uiDest;\n  float4 fDest;\n\n";
    // Every register written before any read, as a compiler's output always has them: a read of an
    // unwritten one would be undefined, and two compilations of it may differ.
    out += "  r0.xyzw = v0.xyzw;\n  r1.xyzw = v1.xyzw;\n  r2.xyz = v2.xyz;\n  r2.w = 1;\n"
           "  r3.xyzw = v0.yzwx;\n  r4.xyzw = v1.wzyx;\n  r5.xyzw = cb0[0].xyzw;\n";
    for (unsigned k = 0; k < 12 && !c_.exhausted(); ++k) out += statement(1);
    if (pixel_) {
      out += "  o0.xyzw = " + value(4, 2) + ";\n";
    } else if (c_.pick(2)) {
      std::string m = matrices_[0].name;
      for (int row = 0; row < 4; ++row)
        out += std::string("  o0.") + kComponents[row] + " = dot(r" + std::to_string(c_.pick(6)) + ".xyzw, " + m + "._m0" +
               std::to_string(row) + "_m1" + std::to_string(row) + "_m2" + std::to_string(row) + "_m3" +
               std::to_string(row) + ");\n";
      out += "  o1.xyzw = " + value(4, 2) + ";\n";
    } else {
      out += "  o0.xyzw = " + value(4, 2) + ";\n  o1.xyzw = " + value(4, 2) + ";\n";
    }
    out += "  return;\n}\n";
    return out;
  }

 private:
  std::string reg() { return "r" + std::to_string(c_.pick(6)); }

  // A swizzle of `n` components, read (any order, repeats) or written (a mask: in order, no repeats).
  std::string swizzle(int n, bool mask) {
    std::string s;
    if (mask) {
      int first = static_cast<int>(c_.pick(static_cast<unsigned>(5 - n)));
      for (int i = 0; i < n; ++i) s += kComponents[first + i];
      return s;
    }
    for (int i = 0; i < n; ++i) s += kComponents[c_.pick(4)];
    return s;
  }

  std::string vectorType(int n) { return n == 1 ? "float" : "float" + std::to_string(n); }

  // A matrix read: one element (`_m21`), several (`_m00_m10_m20`), a row (`M[1]`), through an array.
  std::string matrixValue(int n) {
    const Matrix& m = matrices_[c_.pick(static_cast<unsigned>(matrices_.size()))];
    std::string receiver = m.name;
    if (m.count > 1) receiver += "[" + std::string(c_.pick(2) ? "(uint)" + reg() + ".x % " + std::to_string(m.count) : std::to_string(c_.pick(static_cast<unsigned>(m.count)))) + "]";
    if (c_.pick(4) == 0 && n <= m.columns) {  // a row (the first index), read within its columns
      std::string row = receiver + "[" + std::to_string(c_.pick(static_cast<unsigned>(m.rows))) + "].";
      int first = static_cast<int>(c_.pick(static_cast<unsigned>(m.columns - n + 1)));
      for (int i = 0; i < n; ++i) row += kComponents[first + i];
      return row;
    }
    const bool oneBased = c_.pick(4) == 0;
    std::string s;
    for (int i = 0; i < n; ++i) {
      int row = static_cast<int>(c_.pick(static_cast<unsigned>(m.rows))), column = static_cast<int>(c_.pick(static_cast<unsigned>(m.columns)));
      s += oneBased ? "_" + std::to_string(row + 1) + std::to_string(column + 1)
                    : "_m" + std::to_string(row) + std::to_string(column);
    }
    return receiver + "." + s;
  }

  // An expression of `n` float components, `depth` levels of operators at most.
  std::string value(int n, int depth) {
    const unsigned kinds = depth > 0 ? 21 : 5;
    switch (c_.pick(kinds)) {
      case 0: return reg() + "." + swizzle(n, false);
      case 1: return "cb0[" + std::to_string(c_.pick(static_cast<unsigned>(cbufferRows_))) + "]." + swizzle(n, false);
      case 2: return matrixValue(n);
      case 3: return (c_.pick(2) ? "v1." : "v0.") + swizzle(n, false);
      case 4: {
        std::string s = vectorType(n) + "(";
        for (int i = 0; i < n; ++i) s += (i ? "," : "") + std::to_string(static_cast<int>(c_.pick(5)) - 2);
        return n == 1 ? std::to_string(static_cast<int>(c_.pick(5)) - 2) : s + ")";
      }
      case 5: return value(n, depth - 1) + " * " + value(n, depth - 1) + " + " + value(n, depth - 1);
      case 6: {
        if (n != 1) return "-(" + value(n, depth - 1) + ")";
        int width = 2 + static_cast<int>(c_.pick(3));
        return "dot(" + value(width, depth - 1) + ", " + (c_.pick(2) ? matrixValue(width) : value(width, depth - 1)) + ")";
      }
      case 7: return "mul(" + reg() + ".xyzw, " + matrices_[0].name + ")." + swizzle(n, false);
      case 8: return "mul(" + reg() + ".xyzw, transpose(" + matrices_[0].name + "))." + swizzle(n, false);
      case 9: return "cmp(" + value(n, depth - 1) + (c_.pick(2) ? " < " : " >= ") + value(n, depth - 1) + ")";
      case 10: {
        std::string ones = n == 1 ? "1u" : "uint" + std::to_string(n) + "(1";
        for (int i = 1; i < n; ++i) ones += ",1";
        return "asfloat(asuint(" + value(n, depth - 1) + ") ^ " + ones + (n == 1 ? "" : ")") + ")";
      }
      case 11: return "(int" + (n == 1 ? std::string() : std::to_string(n)) + ")" + reg() + "." + swizzle(n, false) + " | (int" +
                      (n == 1 ? std::string() : std::to_string(n)) + ")" + reg() + "." + swizzle(n, false);
      case 12: return reg() + "." + swizzle(1, false) + " ? " + value(n, depth - 1) + " : " + value(n, depth - 1);
      case 13: {
        std::string at = reg() + "." + swizzle(2, false);
        switch (c_.pick(3)) {
          case 0: return "t0.Load(int3(" + at + ", 0))." + swizzle(n, false);
          case 1: return "t0.SampleLevel(s0_s, " + at + ", 0)." + swizzle(n, false);
          default: return pixel_ ? "t0.Sample(s0_s, " + at + ")." + swizzle(n, false)
                                 : "t0.SampleLevel(s0_s, " + at + ", 1)." + swizzle(n, false);
        }
      }
      // Indices from registers stay in range (an index out of range reads what nobody defined, so two
      // compilations may differ): the register masked, as a compiler's own range proof would allow.
      case 16:  // a cbuffer row picked by a register (skinning, instancing)
        return "cb0[((uint)" + reg() + "." + swizzle(1, false) + " & 3) + " + std::to_string(c_.pick(4)) + "]." +
               swizzle(n, false);
      case 17: return "icb[((uint)" + reg() + "." + swizzle(1, false) + " & 3) + 0]." + swizzle(n, false);
      case 18: {  // a structured buffer's dword at the decompiler's byte offset / 4
        std::string s = n == 1 ? "" : vectorType(n) + "(";
        for (int i = 0; i < n; ++i)
          s += (i ? ", " : "") + std::string("t1[(uint)") + reg() + "." + swizzle(1, false) + " & 3].val[" +
               std::to_string(4 * c_.pick(16)) + "/4]";
        return n == 1 ? s : s + ")";
      }
      case 19: return "f16tof32(asuint(" + value(n, depth - 1) + "))";
      case 20: return pixel_ ? "ddx_coarse(" + value(n, depth - 1) + ")" : "sqrt(abs(" + value(n, depth - 1) + "))";
      case 14: {
        static const char* const unary[] = {"rsqrt", "saturate", "abs", "frac", "sqrt", "exp2", "log2", "-"};
        return std::string(unary[c_.pick(8)]) + "(" + value(n, depth - 1) + ")";
      }
      default: {
        static const char* const binary[] = {"max", "min", "step"};
        return std::string(binary[c_.pick(3)]) + "(" + value(n, depth - 1) + ", " + value(n, depth - 1) + ")";
      }
    }
  }

  std::string statement(int nesting) {
    std::string indent(static_cast<size_t>(2 * nesting), ' ');
    if (nesting < 3 && c_.pick(8) == 0) {
      std::string s = indent + "if (" + reg() + "." + swizzle(1, false) + " != 0) {\n";
      for (unsigned k = 0, n = 1 + c_.pick(3); k < n; ++k) s += statement(nesting + 1);
      if (c_.pick(2)) {
        s += indent + "} else {\n";
        for (unsigned k = 0, n = 1 + c_.pick(3); k < n; ++k) s += statement(nesting + 1);
      }
      return s + indent + "}\n";
    }
    switch (c_.pick(12)) {
      case 0: {  // the decompiler's bitfield insert through `bitmask`
        const char component = kComponents[c_.pick(4)];
        const std::string width = std::to_string(1 + c_.pick(16)), offset = std::to_string(c_.pick(16));
        const std::string target = reg() + "." + component;
        return indent + "bitmask." + component + " = ((~(-1 << " + width + ")) << " + offset + ") & 0xffffffff;  " +
               target + " = (((uint)" + reg() + "." + component + " << " + offset + ") & bitmask." + component +
               ") | ((uint)" + target + " & ~bitmask." + component + ");\n";
      }
      case 1: return indent + "sincos(" + reg() + ".x, " + reg() + ".y, " + reg() + ".z);\n";
      case 2: {  // a texture's size through uiDest
        return indent + "t0.GetDimensions(0, uiDest.x, uiDest.y, uiDest.z);\n" + indent + reg() + ".xy = uiDest.xy;\n";
      }
      default: break;
    }
    int n = 1 + static_cast<int>(c_.pick(4));
    return indent + reg() + "." + swizzle(n, true) + " = " + value(n, 2) + ";\n";
  }

  Choices& c_;
  bool pixel_;
  int cbufferRows_ = 4;
  std::vector<Matrix> matrices_;
};

[[noreturn]] void brokenPromise(const char* what, const SourceFile& input, const TranspileResult& result) {
  std::fprintf(stderr, "fuzz_decompiled_dump: %s\n%s\n--- the dump ---\n%s\n", what,
               result.diagnostics.format().c_str(), input.contents.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Choices choices(data, size);
  const uint8_t setup = choices.byte();
  const bool pixel = setup & 1;
  TranspileOptions options;
  switch ((setup >> 1) & 3) {
    case 0: break;  // a dump's default: 3Dmigoto's StereoParams texture
    case 1: readEyeParamsFrom3DMigoto(options); break;
    case 2: options.eye.source = EyeSource::UniformBlock; break;
    default: options.correctionsOnly = true; break;
  }
  if (setup & 8) options.shiftForm = ShiftForm::Select;
  SourceFile input;
  input.path = std::string("0123456789abcdef-") + (pixel ? "ps" : "vs") + "_replace.txt";
  input.contents = DumpWriter(choices, pixel).write();
  TranspileResult result = transpile(input, options);
  // FUZZ_DUMP_SHOW=1: each dump and what became of it, for looking at what the generator writes.
  if (const char* show = std::getenv("FUZZ_DUMP_SHOW"); show && *show == '1')
    std::fprintf(stderr, "%s--- %s\n%s\n", input.contents.c_str(), result.ok ? "converted" : "refused",
                 result.diagnostics.format().c_str());
  if (!result.ok && !result.diagnostics.hasErrors()) brokenPromise("conversion failed without an error", input, result);
  if (result.ok && result.diagnostics.hasErrors()) brokenPromise("conversion succeeded with an error", input, result);
  return 0;
}
