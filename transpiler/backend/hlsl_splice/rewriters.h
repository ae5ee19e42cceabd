// The HLSL splice's three rewriters, and what they share: the vertex rewriter shifts what each
// entry point returns; the geometry rewriter wraps the argument of every stream Append in the
// shift helper; the domain rewriter renames the entry point and appends a wrapper that shifts its
// SV_Position outputs. Both declare their helpers through the edit
// buffer, in front of the first function that needs them.
#pragma once

#include "transpiler/backend/hlsl_splice.h"
#include "transpiler/backend/hlsl_splice/edit_buffer.h"
#include "transpiler/backend/hlsl_splice/token_view.h"
#include "transpiler/backend/hlsl_splice/shift_text.h"
#include "transpiler/backend/hlsl_splice/top_level.h"

#include <optional>
#include <string>
#include <vector>

namespace stereoshift::hlsl_splice {

// One file being spliced: the options, the scanned and parsed source, the edits made so far.
struct SpliceUnit {
  const HlslSpliceOptions& options;
  const TokenView& view;
  const TopLevel& top;
  EditBuffer& edits;
  int sites = 0;  // shifted outputs so far
};

// A vertex entry point to shift: what to shift, and its definitions (more than one under
// preprocessor conditionals).
struct VertexEntry {
  HlslSplicedEntry wanted;
  std::vector<const Function*> definitions;
};
std::optional<SpliceError> rewriteVertex(SpliceUnit& unit, const std::vector<VertexEntry>& entries);

// `entries`: the definitions of the entry point (more than one under preprocessor conditionals).
std::optional<SpliceError> rewriteGeometry(SpliceUnit& unit, const std::vector<const Function*>& entries);
std::optional<SpliceError> rewriteDomain(SpliceUnit& unit, const std::vector<const Function*>& entries);

// The questions both rewriters ask, by the names the rewriters use.
class Rewriter {
 public:
  explicit Rewriter(SpliceUnit& unit)
      : s_(unit.view.s), opt_(unit.options), toks_(unit.view.tokens), match_(unit.view.match),
        directives_(unit.view.directives), functions_(unit.top.functions), sites_(unit.sites), unit_(unit) {}

 protected:
  std::string_view text(size_t k) const { return unit_.view.text(k); }
  bool isPunct(size_t k, char c) const { return unit_.view.isPunct(k, c); }
  bool isIdent(size_t k) const { return unit_.view.isIdent(k); }
  bool isWord(size_t k, std::string_view w) const { return unit_.view.isWord(k, w); }
  std::string tokSpan(size_t first, size_t last) const { return unit_.view.tokSpan(first, last); }
  SpliceError errAt(size_t tok, std::string msg) const { return unit_.view.errAt(tok, std::move(msg)); }
  std::string where(size_t offset) const { return unit_.view.where(offset); }

  const StructDef* findStruct(const std::string& name) const { return unit_.top.findStruct(name); }
  std::optional<std::string> positionPath(const std::string& name) const { return unit_.top.positionPath(name); }
  const Function* enclosingFunction(size_t tok) const { return unit_.top.enclosingFunction(tok); }
  std::optional<SpliceError> checkConflicts(const std::vector<std::string>& ours) const {
    return hlsl_splice::checkConflicts(unit_.view, unit_.top, ours, opt_.cbufferRegister, !opt_.stereoParamsTexture);
  }

  void addEdit(size_t offset, size_t remove, std::string insert) { unit_.edits.add(offset, remove, std::move(insert)); }
  std::string newline() const { return unit_.edits.newline(); }
  void insertBlockBefore(size_t offset, size_t notBefore, const std::string& block) {
    hlsl_splice::insertBlockBefore(unit_.edits, unit_.view, offset, notBefore, block);
  }
  void insertBlockAfter(size_t tok, const std::string& block) {
    hlsl_splice::insertBlockAfter(unit_.edits, unit_.view, tok, block);
  }
  std::string preambleText(const std::vector<ShiftHelper>& helpers) const {
    return hlsl_splice::preambleText(opt_, helpers, unit_.edits.newline());
  }

  const std::string& s_;
  const HlslSpliceOptions& opt_;
  const std::vector<Token>& toks_;
  const std::vector<size_t>& match_;
  const std::vector<Directive>& directives_;
  const std::vector<Function>& functions_;
  int& sites_;

 private:
  SpliceUnit& unit_;
};

}  // namespace stereoshift::hlsl_splice
