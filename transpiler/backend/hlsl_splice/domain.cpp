// The HLSL splice's domain rewriter: this turns a domain shader's entry point into
// `<entry>_stereoshift_mono` (its attributes left behind as a comment) and appends a wrapper of
// the original name, attributes, parameters and return semantic that calls it and shifts every
// SV_Position output: the return value, a member of a returned struct, or an `out` parameter.
#include "transpiler/backend/hlsl_splice/rewriters.h"

#include <algorithm>
#include <utility>

namespace stereoshift::hlsl_splice {

namespace {

class DomainRewriter : Rewriter {
 public:
  using Rewriter::Rewriter;

  std::optional<SpliceError> run(const std::vector<const Function*>& entries) {
    std::vector<ShiftHelper> shifts;
    auto needShift = [&](const std::string& type, const std::string& access) -> const ShiftHelper& {
      std::string fn = std::string(kPrefix) + "_shift_" + (access.empty() ? std::string("position") : type);
      for (const auto& sh : shifts) {
        if (sh.function == fn) return sh;
      }
      shifts.push_back({access.empty() ? std::string("float4") : type, fn, access, {}});
      return shifts.back();
    };
    std::string mono = opt_.entryPoint + "_" + kPrefix + "_mono";
    struct Plan {
      const Function* f;
      std::string returnShift;  // helper for the return value, "" if none
      std::vector<std::pair<std::string, std::string>> outShifts;  // (param, helper)
    };
    std::vector<Plan> plans;
    for (const Function* f : entries) {
      Plan plan{f, {}, {}};
      // Return type: identifiers between the attributes and the name.
      std::string retType;
      for (size_t t = f->typeBegin; t < f->nameTok; ++t) {
        if (isPunct(t, '<')) break;
        if (isIdent(t) && !modifierWords().count(std::string(text(t)))) retType = std::string(text(t));
      }
      std::string retSemantic = f->semTok != npos ? lower(text(f->semTok)) : "";
      if (isPositionSemantic(retSemantic) && isFloat4Like(retType)) {
        plan.returnShift = needShift(retType, "").function;
      } else if (auto path = positionPath(retType)) {
        plan.returnShift = needShift(retType, *path).function;
      }
      for (const auto& p : f->params) {
        if (p.name.empty()) return errAt(p.begin, "parameter without a name");
        if (!p.isOut) continue;
        if (isPositionSemantic(p.semantic) && isFloat4Like(p.typeName)) {
          plan.outShifts.push_back({p.name, needShift(p.typeName, "").function});
        } else if (auto path = positionPath(p.typeName)) {
          plan.outShifts.push_back({p.name, needShift(p.typeName, *path).function});
        }
      }
      if (plan.returnShift.empty() && plan.outShifts.empty()) {
        return errAt(f->nameTok, "domain entry point '" + opt_.entryPoint +
                                     "' has no SV_Position output (return value, struct member or out parameter)");
      }
      plans.push_back(std::move(plan));
    }
    std::vector<std::string> ours = {opt_.cbufferName, opt_.eyeSignName, opt_.separationName, opt_.convergenceName,
                                     mono};
    for (const auto& sh : shifts) ours.push_back(sh.function);
    if (auto err = checkConflicts(ours)) return err;

    // Preamble before the first entry definition, after the structs it needs.
    size_t first = npos;
    for (const Function* f : entries) first = std::min(first, toks_[f->declBegin].begin);
    size_t notBefore = 0;
    for (const auto& sh : shifts) {
      if (const StructDef* sd = findStruct(sh.type)) notBefore = std::max(notBefore, toks_[sd->endTok].end);
    }
    insertBlockBefore(first, notBefore, preambleText(shifts));

    std::string nl = newline();
    for (const auto& plan : plans) {
      const Function* f = plan.f;
      // Attributes move to the wrapper; a comment keeps the line structure of the original.
      std::string attrs;
      for (const auto& a : f->attrs) {
        std::string at = tokSpan(a.open, a.close);
        attrs += at + nl;
        size_t b = toks_[a.open].begin;
        addEdit(b, at.size(), at.find("*/") == npos ? "/* stereoshift: moved to the wrapper: " + at + " */" : std::string());
      }
      addEdit(toks_[f->nameTok].begin, toks_[f->nameTok].end - toks_[f->nameTok].begin, mono);

      std::string retType = f->typeBegin < f->nameTok ? tokSpan(f->typeBegin, f->nameTok - 1) : "void";
      bool isVoid = retType == "void";
      std::string args;
      for (const auto& p : f->params) args += (args.empty() ? "" : ", ") + p.name;
      std::string call = mono + "(" + args + ")";
      std::string body;
      std::string ind = "    ";
      if (!isVoid && !plan.returnShift.empty() && plan.outShifts.empty()) {
        body = ind + "return " + plan.returnShift + "(" + call + ");" + nl;
      } else {
        std::string result = std::string(kPrefix) + "_result";
        body = isVoid ? ind + call + ";" + nl : ind + retType + " " + result + " = " + call + ";" + nl;
        if (!plan.returnShift.empty()) body += ind + result + " = " + plan.returnShift + "(" + result + ");" + nl;
        for (const auto& [param, helper] : plan.outShifts) body += ind + param + " = " + helper + "(" + param + ");" + nl;
        if (!isVoid) body += ind + "return " + result + ";" + nl;
      }
      std::string wrapper = "// ---- stereoshift: entry point wrapper, shifts the clip position of '" + mono + "' ----" + nl;
      wrapper += attrs + retType + " " + opt_.entryPoint + tokSpan(f->paramOpen, f->paramClose);
      if (f->semTok != npos) wrapper += " : " + std::string(text(f->semTok));
      wrapper += nl + "{" + nl + body + "}" + nl + "// ---- end stereoshift ----" + nl;
      insertBlockAfter(f->bodyClose, wrapper);
      sites_ += static_cast<int>((plan.returnShift.empty() ? 0 : 1) + plan.outShifts.size());
    }
    return std::nullopt;
  }
};

}  // namespace

std::optional<SpliceError> rewriteDomain(SpliceUnit& unit, const std::vector<const Function*>& entries) {
  return DomainRewriter(unit).run(entries);
}

}  // namespace stereoshift::hlsl_splice
