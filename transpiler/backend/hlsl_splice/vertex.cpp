// The HLSL splice's vertex rewriter: this turns each vertex entry point into its stereo version in
// place. Every `return e;` of the entry point becomes `return stereoshift_shift_T(e);` when it
// returns the clip position (a float4 with semantic SV_Position, or a struct with an SV_Position
// member, nested structs included); `out` parameters that carry it are shifted before every return
// and at the end of the body. The function keeps its name, attributes, parameters and semantics,
// and the structs keep their members in the order written: D3D links the vertex outputs to the
// pixel shader's inputs by register, in declaration order, so the unchanged pixel shader still
// matches. Halo copies (members or parameters the passes found equal to the clip position) are
// shifted by the same helper.
#include "transpiler/backend/hlsl_splice/rewriters.h"
#include "transpiler/backend/hlsl_splice/shift_text.h"

#include <algorithm>
#include <utility>

namespace stereoshift::hlsl_splice {

namespace {

class VertexRewriter : Rewriter {
 public:
  using Rewriter::Rewriter;

  std::optional<SpliceError> run(const std::vector<VertexEntry>& entries) {
    struct Plan {
      const Function* f;
      std::string returnShift;                                     // helper for the return value
      std::vector<std::pair<std::string, std::string>> outShifts;  // (param, helper)
      std::string movedLanes;                                      // statements before the shifts
    };
    std::vector<Plan> plans;
    for (const auto& entry : entries) {
      for (const Function* f : entry.definitions) {
        auto plan = planEntry(*f, entry.wanted);
        if (!plan) return plan.error;
        plans.push_back({f, plan.returnShift, plan.outShifts, plan.movedLanes});
      }
    }
    std::vector<std::string> ours = {opt_.cbufferName, opt_.eyeSignName, opt_.separationName, opt_.convergenceName};
    for (const auto& sh : helpers_) ours.push_back(sh.function);
    if (auto err = checkConflicts(ours)) return err;

    // The preamble goes before the first shifted entry point, after the structs it names.
    size_t first = npos;
    for (const auto& plan : plans) first = std::min(first, toks_[plan.f->declBegin].begin);
    size_t notBefore = 0;
    for (const auto& sh : helpers_) {
      const StructDef* sd = findStruct(sh.type);
      if (!sd) continue;
      if (toks_[sd->endTok].end > first) {
        return errAt(sd->nameTok, "struct '" + sh.type + "' is defined after its first use at " + where(first));
      }
      notBefore = std::max(notBefore, toks_[sd->endTok].end);
    }
    insertBlockBefore(first, notBefore, preambleText(helpers_));

    for (const auto& plan : plans) {
      if (auto err = rewriteReturns(*plan.f, plan.returnShift, plan.outShifts, plan.movedLanes)) return err;
    }
    for (const auto& camera : opt_.cameras)
      if (auto err = wrapCameraReads(camera, first)) return err;
    return std::nullopt;
  }

 private:
  // Every read of the camera in a function body wrapped in its helper, which the preamble (at
  // `preamble`) defines: a read before it, a local or parameter hiding the camera's name, a name
  // inside a macro or a camera it does not name plainly is refused (the IR's re-emit carries it).
  std::optional<SpliceError> wrapCameraReads(const HlslSpliceOptions::CameraWrap& camera, size_t preamble) {
    int reads = 0;
    for (const Function& f : functions_) {
      for (const Param& p : f.params)
        if (p.name == camera.access) return errAt(p.nameTok, "a parameter named '" + camera.access + "' hides the camera");
      for (size_t t = f.bodyOpen + 1; t < f.bodyClose; ++t) {
        if (!isWord(t, camera.access) || isPunct(t - 1, '.')) continue;
        if (isIdent(t - 1) && text(t - 1) != "return")
          return errAt(t, "a local named '" + camera.access + "' hides the camera");
        if (toks_[t].begin < preamble) return errAt(t, "the camera '" + camera.access + "' is read before the entry point");
        addEdit(toks_[t].begin, 0, camera.function + "(");
        addEdit(toks_[t].end, 0, ")");
        ++reads;
      }
    }
    for (const auto& d : directives_)
      for (const Token& t : d.body)
        if (s_.compare(t.begin, t.end - t.begin, camera.access) == 0)
          return SpliceError{d.begin, "the camera '" + camera.access + "' is named in a macro", false};
    if (reads == 0) return SpliceError{npos, "the camera '" + camera.access + "' is not read in a function of the text", false};
    return std::nullopt;
  }

  struct EntryPlan {
    std::optional<SpliceError> error;
    std::string returnShift;
    std::vector<std::pair<std::string, std::string>> outShifts;
    std::string movedLanes;
    explicit operator bool() const { return !error; }
  };

  // The moved lanes as statements: each an `out` parameter of `f` moved by its coefficient times
  // the shift of x of the SV_Position `out` parameter (helper `stereoshift_shift_position`).
  std::optional<SpliceError> planMovedLanes(const Function& f, const HlslSplicedEntry& wanted, EntryPlan& plan) {
    if (wanted.movedLanes.empty()) return std::nullopt;
    std::string position;
    for (const auto& p : f.params)
      if (p.isOut && isPositionSemantic(p.semantic) && isFloat4Like(p.typeName)) position = p.name;
    if (position.empty())
      return errAt(f.nameTok, "the output '" + wanted.movedLanes.front().output +
                                  "' moves with the clip position's x, which is no SV_Position out parameter of '" +
                                  std::string(text(f.nameTok)) + "'");
    const std::string shift = needShift("float4", "", {}, true).function;
    for (const auto& moved : wanted.movedLanes) {
      auto out = std::find_if(f.params.begin(), f.params.end(), [&](const Param& p) { return p.isOut && p.name == moved.output; });
      if (out == f.params.end() || moved.lane > 3)
        return errAt(f.nameTok, "the output '" + moved.output + "' that moves with the clip position's x is not an out "
                                "parameter of '" + std::string(text(f.nameTok)) + "'");
      const std::string lane(1, "xyzw"[moved.lane]);
      plan.movedLanes += moved.output + "." + lane + " += " + floatLiteral(moved.coefficient) + " * (" + shift + "(" +
                         position + ").x - " + position + ".x); ";
    }
    return std::nullopt;
  }

  // The helper that shifts `access` (and `copies`) of a value of `type`, declared once.
  const ShiftHelper& needShift(const std::string& type, const std::string& access, std::vector<std::string> copies,
                               bool positionToo = true) {
    std::sort(copies.begin(), copies.end());
    std::string base = std::string(kPrefix) + "_shift_" +
                       (access.empty() ? std::string(positionToo ? "position" : "copy") : type);
    std::string fn = base;
    for (int n = 2;; ++n) {
      auto same = std::find_if(helpers_.begin(), helpers_.end(), [&](const ShiftHelper& h) { return h.function == fn; });
      if (same == helpers_.end()) break;
      if (same->type == type && same->access == access && same->copies == copies && same->positionToo == positionToo)
        return *same;
      fn = base + "_" + std::to_string(n);  // the same struct with another set of halo copies
    }
    helpers_.push_back({access.empty() ? std::string("float4") : type, fn, access, copies, positionToo});
    return helpers_.back();
  }

  std::string returnTypeName(const Function& f) const {
    std::string type;
    for (size_t t = f.typeBegin; t < f.nameTok; ++t) {
      if (isPunct(t, '<')) break;
      if (isIdent(t) && !modifierWords().count(std::string(text(t)))) type = std::string(text(t));
    }
    return type;
  }

  // The members of struct `type` named by `copies` (".member" paths): each must be a float4.
  std::optional<SpliceError> checkMemberCopies(const Function& f, const std::string& type,
                                               const std::vector<std::string>& copies) const {
    const StructDef* sd = findStruct(type);
    for (const auto& path : copies) {
      bool found = false;
      for (const auto& m : sd ? sd->members : std::vector<Member>{}) {
        if ("." + m.name == path && isFloat4Like(m.typeName)) found = true;
      }
      if (!found) {
        return errAt(f.nameTok, "the halo copy '" + path.substr(1) + "' of '" + std::string(text(f.nameTok)) +
                                    "' is not a float4 member of its output struct '" + type + "'");
      }
    }
    return std::nullopt;
  }

  EntryPlan planEntry(const Function& f, const HlslSplicedEntry& wanted) {
    EntryPlan plan;
    std::vector<std::string> memberCopies, paramCopies;
    for (const auto& c : wanted.copies) (c.starts_with(".") ? memberCopies : paramCopies).push_back(c);
    std::string retType = returnTypeName(f);
    std::string retSemantic = f.semTok != npos ? lower(text(f.semTok)) : "";
    // --corrections-only: the driver shifts the position; only its copies are shifted here.
    const bool position = !opt_.correctionsOnly;
    if (isPositionSemantic(retSemantic) && isFloat4Like(retType)) {
      if (position) plan.returnShift = needShift(retType, "", {}).function;
    } else if (auto path = positionPath(retType)) {
      if (auto err = checkMemberCopies(f, retType, memberCopies)) {
        plan.error = err;
        return plan;
      }
      if (position || !memberCopies.empty()) plan.returnShift = needShift(retType, *path, memberCopies, position).function;
      memberCopies.clear();
    }
    for (const auto& p : f.params) {
      if (p.name.empty()) {
        plan.error = errAt(p.begin, "parameter without a name");
        return plan;
      }
      if (!p.isOut) continue;
      bool isCopy = std::find(paramCopies.begin(), paramCopies.end(), p.name) != paramCopies.end();
      if ((isPositionSemantic(p.semantic) || isCopy) && isFloat4Like(p.typeName)) {
        if (position || isCopy) plan.outShifts.push_back({p.name, needShift(p.typeName, "", {}, position || isCopy).function});
        if (isCopy) paramCopies.erase(std::find(paramCopies.begin(), paramCopies.end(), p.name));
      } else if (auto path = positionPath(p.typeName)) {
        if (position) plan.outShifts.push_back({p.name, needShift(p.typeName, *path, {}).function});
      }
    }
    if (auto err = planMovedLanes(f, wanted, plan)) {
      plan.error = err;
      return plan;
    }
    std::vector<std::string> unplaced = memberCopies;
    unplaced.insert(unplaced.end(), paramCopies.begin(), paramCopies.end());
    if (!unplaced.empty()) {
      plan.error = errAt(f.nameTok, "the halo copy '" + unplaced.front() + "' of '" + std::string(text(f.nameTok)) +
                                        "' is not a float4 output the text can shift");
    } else if (plan.returnShift.empty() && plan.outShifts.empty() && plan.movedLanes.empty()) {
      plan.error = errAt(f.nameTok, "vertex entry point '" + std::string(text(f.nameTok)) +
                                        "' has no SV_Position output (return value, struct member or out parameter)");
    }
    return plan;
  }

  // The ';' that ends the statement starting at token `k` (brackets skipped), or npos.
  size_t statementEnd(size_t k, size_t limit) const {
    while (k < limit && !isPunct(k, ';')) {
      if (isPunct(k, '(') || isPunct(k, '[') || isPunct(k, '{')) k = match_[k];
      ++k;
    }
    return k < limit ? k : npos;
  }

  std::optional<SpliceError> rewriteReturns(const Function& f, const std::string& returnShift,
                                            const std::vector<std::pair<std::string, std::string>>& outShifts,
                                            const std::string& movedLanes) {
    std::string outAssignments = movedLanes;  // from the position before it is shifted
    for (const auto& [param, helper] : outShifts) outAssignments += param + " = " + helper + "(" + param + "); ";
    bool endsInReturn = false;
    int depth = 0;
    for (size_t t = f.bodyOpen + 1; t < f.bodyClose; ++t) {
      if (isPunct(t, '{')) ++depth;
      if (isPunct(t, '}')) --depth;
      if (!isWord(t, "return")) continue;
      size_t semi = statementEnd(t + 1, f.bodyClose);
      if (semi == npos) return errAt(t, "return statement without ';'");
      if (!returnShift.empty()) {
        if (semi == t + 1) return errAt(t, "return without a value in an entry point that returns the clip position");
        addEdit(toks_[t + 1].begin, 0, returnShift + "(");
        addEdit(toks_[semi].begin, 0, ")");
      }
      if (!outAssignments.empty()) {
        addEdit(toks_[t].begin, 0, "{ " + outAssignments);
        addEdit(toks_[semi].end, 0, " }");
      }
      ++sites_;
      // A top-level `return` that is the body's last statement: nothing to shift after it.
      bool statementStart = isPunct(t - 1, ';') || isPunct(t - 1, '{') || isPunct(t - 1, '}');
      endsInReturn = depth == 0 && statementStart && semi + 1 == f.bodyClose;
    }
    if (!outAssignments.empty() && !endsInReturn) {
      // Falling off the end of the body: shift the out parameters just before the closing brace.
      size_t close = toks_[f.bodyClose].begin;
      size_t ls = close;
      while (ls > 0 && (s_[ls - 1] == ' ' || s_[ls - 1] == '\t')) --ls;
      if (ls == 0 || s_[ls - 1] == '\n') {
        addEdit(ls, 0, "    " + outAssignments.substr(0, outAssignments.size() - 1) + newline());
      } else {
        addEdit(close, 0, outAssignments);
      }
      ++sites_;
    }
    if (returnShift.empty() && outShifts.empty() && movedLanes.empty()) return errAt(f.nameTok, "nothing to shift");
    return std::nullopt;
  }

  std::vector<ShiftHelper> helpers_;
};

}  // namespace

std::optional<SpliceError> rewriteVertex(SpliceUnit& unit, const std::vector<VertexEntry>& entries) {
  return VertexRewriter(unit).run(entries);
}

}  // namespace stereoshift::hlsl_splice
