// The HLSL splice's rendering of the shift: see shift_text.h.
#include "transpiler/backend/hlsl_splice/shift_text.h"

#include "transpiler/backend/hlsl_splice/token_view.h"

#include <cstdio>

namespace stereoshift::hlsl_splice {

std::string floatLiteral(float value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(value));
  std::string lit = buf;
  if (lit.find_first_of(".eE") == npos) lit += ".0";
  return lit + "f";
}

namespace {

std::string epsilonLiteral(float epsilon) { return floatLiteral(epsilon); }

// eyeSign * separation, or the separation alone where it carries the eye's sign (3Dmigoto's).
std::string eyeOffset(const ShiftSpec& spec) {
  return spec.eyeSignName.empty() ? spec.separationName : spec.eyeSignName + " * " + spec.separationName;
}

// When `p` (the position) is shifted: the condition of emitCutoffCondition, in its order.
std::string conditionText(const ShiftSpec& spec, const std::string& p) {
  // Even without a cutoff, a mono draw (eyeSign 0) runs none of the shift; 3Dmigoto's mono is a
  // separation of 0, which shifts by nothing.
  std::string stereo = spec.eyeSignName.empty() ? spec.separationName + " != 0.0f" : spec.eyeSignName + " != 0.0f";
  switch (spec.cutoff) {
    case CutoffMode::Epsilon:
      // Same guard as the SPIR-V route: an infinite w is never shifted (0 * inf would be NaN).
      return stereo + " && abs(" + p + ".w - 1.0f) > " + epsilonLiteral(spec.epsilon) + " && !isinf(" + p + ".w)";
    case CutoffMode::Exact:
      return stereo + " && " + p + ".w != 1.0f && !isinf(" + p + ".w)";
    case CutoffMode::None:
      break;
  }
  return stereo;
}

// Statements that leave the shifted x of `p` in `result` (declared by them), one per line.
std::vector<std::string> shiftedXStatements(const ShiftSpec& spec, const std::string& p, const std::string& result) {
  const std::string x = p + ".x", w = p + ".w";
  const std::string& c = spec.convergenceName;
  if (spec.compensated) {
    // emitShiftedX's error-free transformations, operation for operation: w - C exactly as dh + dl
    // (TwoSum), a*dh exactly as ph + pl (Dekker's TwoProduct with a Veltkamp split), x + ph exactly
    // as sh + sl (TwoSum), one final rounding of sh + (sl + pl + a*dl). Every temporary `precise`:
    // none of it survives re-association or contraction.
    auto t = [](const char* name) { return std::string(kPrefix) + "_" + name; };
    std::vector<std::string> code;
    auto let = [&](const std::string& name, const std::string& value) {
      code.push_back("precise float " + name + " = " + value + ";");
    };
    let(t("dh"), w + " - " + c);
    let(t("db"), t("dh") + " - " + w);
    let(t("dl"), "(" + w + " - (" + t("dh") + " - " + t("db") + ")) - (" + c + " + " + t("db") + ")");
    let(t("a"), eyeOffset(spec));
    let(t("ph"), t("a") + " * " + t("dh"));
    for (const char* v : {"a", "dh"}) {
      std::string name = t(v);
      let(name + "_c", "4097.0f * " + name);
      let(name + "_hi", name + "_c - (" + name + "_c - " + name + ")");
      let(name + "_lo", name + " - " + name + "_hi");
    }
    let(t("pl"), "(((" + t("a_hi") + " * " + t("dh_hi") + " - " + t("ph") + ") + " + t("a_hi") + " * " + t("dh_lo") +
                     ") + " + t("a_lo") + " * " + t("dh_hi") + ") + " + t("a_lo") + " * " + t("dh_lo"));
    let(t("sh"), x + " + " + t("ph"));
    let(t("sb"), t("sh") + " - " + x);
    let(t("sl"), "(" + x + " - (" + t("sh") + " - " + t("sb") + ")) + (" + t("ph") + " - " + t("sb") + ")");
    let(result, t("sh") + " + (" + t("sl") + " + (" + t("pl") + " + " + t("a") + " * " + t("dl") + "))");
    return code;
  }
  std::string shifted = spec.fused
                            // One rounding less, as the SPIR-V route's Fma is emitted for HLSL.
                            ? "mad(" + eyeOffset(spec) + ", " + w + " - " + c + ", " + x + ")"
                            : x + " + (" + eyeOffset(spec) + ") * (" + w + " - " + c + ")";
  return {(spec.precise ? "precise float " : "float ") + result + " = " + shifted + ";"};
}

}  // namespace

std::string cbufferText(const HlslSpliceOptions& opt, const std::string& nl) {
  std::string extra;
  for (const auto& name : opt.extraParams) extra += "    float " + name + ";" + nl;
  return "cbuffer " + opt.cbufferName + " : register(b" + std::to_string(opt.cbufferRegister) + ")" + nl + "{" + nl +
         "    float " + opt.eyeSignName + ";" + nl + "    float " + opt.separationName + ";" + nl + "    float " +
         opt.convergenceName + ";" + nl + extra + "};" + nl;
}

// The inverse of a 4x4 matrix by cofactors (HLSL has no intrinsic): the 2x2 minors of rows 0-1
// (s) and rows 2-3 (c), the determinant from them, each element of the adjugate over it.
std::string inverseFunctionText(const std::string& nl) {
  const char* lines[] = {
      "float4x4 stereoshift_inverse(float4x4 m)",
      "{",
      "    float s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1], s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];",
      "    float s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3], s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];",
      "    float s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3], s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];",
      "    float c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3], c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];",
      "    float c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2], c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];",
      "    float c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2], c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];",
      "    float d = 1.0f / (s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0);",
      "    return float4x4(",
      "        ( m[1][1] * c5 - m[1][2] * c4 + m[1][3] * c3) * d, (-m[0][1] * c5 + m[0][2] * c4 - m[0][3] * c3) * d,",
      "        ( m[3][1] * s5 - m[3][2] * s4 + m[3][3] * s3) * d, (-m[2][1] * s5 + m[2][2] * s4 - m[2][3] * s3) * d,",
      "        (-m[1][0] * c5 + m[1][2] * c2 - m[1][3] * c1) * d, ( m[0][0] * c5 - m[0][2] * c2 + m[0][3] * c1) * d,",
      "        (-m[3][0] * s5 + m[3][2] * s2 - m[3][3] * s1) * d, ( m[2][0] * s5 - m[2][2] * s2 + m[2][3] * s1) * d,",
      "        ( m[1][0] * c4 - m[1][1] * c2 + m[1][3] * c0) * d, (-m[0][0] * c4 + m[0][1] * c2 - m[0][3] * c0) * d,",
      "        ( m[3][0] * s4 - m[3][1] * s2 + m[3][3] * s0) * d, (-m[2][0] * s4 + m[2][1] * s2 - m[2][3] * s0) * d,",
      "        (-m[1][0] * c3 + m[1][1] * c1 - m[1][2] * c0) * d, ( m[0][0] * c3 - m[0][1] * c1 + m[0][2] * c0) * d,",
      "        (-m[3][0] * s3 + m[3][1] * s1 - m[3][2] * s0) * d, ( m[2][0] * s3 - m[2][1] * s1 + m[2][2] * s0) * d);",
      "}"};
  std::string t;
  for (const char* line : lines) t += std::string(line) + nl;
  return t;
}

std::string shiftFunctionText(const HlslSpliceOptions& spec, const ShiftHelper& helper, const std::string& nl) {
  const std::string v = std::string(kPrefix) + "_v";
  const std::string ind = "    ";
  std::string body;
  // 3Dmigoto's parameters: texel 0 of StereoParams, read once per call.
  if (spec.stereoParamsTexture) body += ind + "float4 " + spec.cbufferName + " = StereoParams.Load(int3(0, 0, 0));" + nl;
  auto lines = [&](const std::vector<std::string>& code, const std::string& in) {
    for (const auto& line : code) body += in + line + nl;
  };
  std::vector<std::string> accesses;
  if (helper.positionToo) accesses.push_back(helper.access);
  accesses.insert(accesses.end(), helper.copies.begin(), helper.copies.end());
  for (size_t k = 0; k < accesses.size(); ++k) {
    const std::string p = v + accesses[k];
    // One temporary name per shifted member, so the helper stays one flat block.
    const std::string tmp = std::string(kPrefix) + "_x" + (k ? std::to_string(k) : std::string());
    if (spec.form == ShiftForm::Select) {
      // Branch-free, like the SPIR-V route's OpSelect: the shift is computed, the cutoff picks. A
      // copy's statements get a scope of their own (the compensated temporaries have fixed names).
      std::string in = k ? ind + ind : ind;
      if (k) body += ind + "{" + nl;
      lines(shiftedXStatements(spec, p, tmp), in);
      body += in + p + ".x = (" + conditionText(spec, p) + ") ? " + tmp + " : " + p + ".x;" + nl;
      if (k) body += ind + "}" + nl;
    } else {
      body += ind + "if (" + conditionText(spec, p) + ")" + nl + ind + "{" + nl;
      if (!spec.precise && !spec.compensated && !spec.fused) {
        body += ind + ind + p + ".x = " + p + ".x + (" + eyeOffset(spec) + ") * (" + p + ".w - " + spec.convergenceName +
                ");" + nl;
      } else {
        lines(shiftedXStatements(spec, p, tmp), ind + ind);
        body += ind + ind + p + ".x = " + tmp + ";" + nl;
      }
      body += ind + "}" + nl;
    }
  }
  return helper.type + " " + helper.function + "(" + helper.type + " " + v + ")" + nl + "{" + nl + body + ind +
         "return " + v + ";" + nl + "}" + nl;
}

std::string preambleText(const HlslSpliceOptions& options, const std::vector<ShiftHelper>& helpers,
                         const std::string& nl) {
  std::string t = "// ---- stereoshift: stereo parameters and clip-space shift (injected) ----" + nl;
  if (!options.stereoParamsTexture)
    t += cbufferText(options, nl) + nl;
  else if (options.declareStereoParams)
    t += "Texture2D<float4> StereoParams : register(t125);" + nl + nl;
  for (size_t k = 0; k < helpers.size(); ++k) t += (k ? nl : "") + shiftFunctionText(options, helpers[k], nl);
  if (options.inverse) t += inverseFunctionText(nl);
  for (const auto& c : options.cameras) {
    std::string offset = c.type == "float4" ? "float4(" + c.offset + ", 0.0f)" : c.offset;
    t += c.type + " " + c.function + "(" + c.type + " stereoshift_camera)" + nl + "{" + nl +
         "    return stereoshift_camera + " + offset + ";" + nl + "}" + nl;
  }
  t += "// ---- end stereoshift ----" + nl;
  return t;
}

}  // namespace stereoshift::hlsl_splice
