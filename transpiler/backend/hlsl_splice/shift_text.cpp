// The HLSL splice's rendering of the shift: see shift_text.h.
#include "transpiler/backend/hlsl_splice/shift_text.h"

#include "transpiler/backend/hlsl_splice/token_view.h"

#include <cstdio>

namespace stereoshift::hlsl_splice {

namespace {

std::string epsilonLiteral(float epsilon) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(epsilon));
  std::string lit = buf;
  if (lit.find_first_of(".eE") == npos) lit += ".0";
  return lit + "f";
}

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
  return "cbuffer " + opt.cbufferName + " : register(b" + std::to_string(opt.cbufferRegister) + ")" + nl + "{" + nl +
         "    float " + opt.eyeSignName + ";" + nl + "    float " + opt.separationName + ";" + nl + "    float " +
         opt.convergenceName + ";" + nl + "};" + nl;
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
  t += "// ---- end stereoshift ----" + nl;
  return t;
}

}  // namespace stereoshift::hlsl_splice
