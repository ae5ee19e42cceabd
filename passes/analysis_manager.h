// The analysis manager: every analysis of one module, computed on first request, memoized, and
// dropped when a pass changes the module without preserving it (SPIRV-Tools' IRContext analyses,
// LLVM's analysis manager in miniature). A pass's registry entry declares the analyses it reads
// and those that stay valid after it changed the module; the pass manager drops the others, and
// with --validate-each checks each claim first (checkPreserved).
//
// One manager per stage: the driver's stage plan owns it, so the analyses a pipeline-wide question
// makes of a stage (the next-stage facts of the fragment stage) serve that stage's own passes too.
#pragma once

#include "passes/analysis/clip_positions.h"
#include "passes/analysis/value_flow.h"
#include "passes/analysis/value_numbers.h"
#include "passes/analysis/view_vector_flow.h"
#include "passes/ir/module.h"
#include "passes/next_stage_facts.h"
#include "core/shader.h"

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace stereoshift {

enum Analysis : unsigned {
  kClipPositionAnalysis = 1u << 0,    // the position outputs, their pointers, the mono values
  kFoldedCopyAnalysis = 1u << 1,      // the inlined, constant-folded copy (and what is built on it)
  kValueFlowAnalysis = 1u << 2,       // value flow (def-use, memory, calls) of the module
  kValueNumberAnalysis = 1u << 3,     // value numbers of the module
  kStageInputAnalysis = 1u << 4,      // how this stage uses its inputs (the next-stage facts it gives)
};
using AnalysisSet = unsigned;
constexpr AnalysisSet kNoAnalyses = 0;
constexpr AnalysisSet kAllAnalyses = kClipPositionAnalysis | kFoldedCopyAnalysis | kValueFlowAnalysis |
                                     kValueNumberAnalysis | kStageInputAnalysis;
const char* analysisName(Analysis analysis);

class AnalysisManager {
 public:
  // `source` and `file` name the stage for the facts it gives the stage before it. `foldedCopy`
  // false: the optimizer is never run (an earlier attempt of this conversion crashed in it), and
  // every question the folded copy would answer is asked of the module as it is.
  AnalysisManager(const spirv::Module& module, const SourceInfo& source, std::string file, bool foldedCopy = true);
  AnalysisManager(const AnalysisManager&) = delete;
  AnalysisManager& operator=(const AnalysisManager&) = delete;
  ~AnalysisManager();

  const spirv::Module& module() const { return module_; }

  // The clip-position analysis of the module as it is now.
  const ClipPositionAnalysis& clipPositions();
  // An inlined, constant-folded throw-away copy of the module (SPIRV-Tools' performance passes),
  // for questions that must see through helper functions and structs. Only used to answer
  // questions, never emitted; global ids (variables) are the module's own. Null when the optimizer
  // cannot process the module.
  const spirv::Module* foldedCopy();
  // The folded copy with the components of function variables in SSA form as well (constant-index
  // access chains converted first): each write of a decompiled shader's register components
  // (`r1.x = ...`) its own value, whatever the register held before. The same copy otherwise;
  // part of the folded-copy analysis.
  const spirv::Module* registerSsaCopy();
  // Value flow of the module (analysis/value_flow.h).
  const analysis::ValueFlow& valueFlow();
  // Value numbers of the module (analysis/value_numbers.h).
  const analysis::ValueNumbers& valueNumbers();
  // The view-vector queries of per-eye-view on the folded copy; null without one. Part of the
  // folded-copy analysis: dropped with it.
  analysis::ViewVectorFlow* foldedViewVectorFlow();
  // How this stage uses its inputs: which feed texture coordinates (for the stage before it).
  // `consumer`: the facts of the stage after this one, for a stage between (geometry,
  // tessellation): each input gets the uses of the outputs it is written to. Null for the last.
  const NextStageFacts& stageInputUses(const NextStageFacts* consumer = nullptr);

  // Drops every analysis not in `kept` (after a pass changed the module).
  void invalidate(AnalysisSet kept);
  // The analyses computed right now.
  AnalysisSet cached() const;
  // Whether each analysis of `claimed` that is cached still describes the module: "" when every
  // claim holds, else the name of the first that does not. A fresh computation is compared with
  // the cached one where the answers are comparable (clip positions, stage input uses); the folded
  // copy must still name only global ids the module has, with the same type; value flow and value
  // numbers must still index only instructions the module has (they point into it).
  std::string checkPreserved(AnalysisSet claimed);

 private:
  const spirv::Module& module_;
  SourceInfo source_;
  std::string file_;
  std::optional<ClipPositionAnalysis> clipPositions_;
  std::optional<spirv::Module> folded_;
  bool foldTried_ = false;
  bool foldingAllowed_ = true;
  std::optional<spirv::Module> registers_;
  bool registerTried_ = false;
  std::unique_ptr<analysis::ViewVectorFlow> foldedFlow_;
  std::unique_ptr<analysis::ValueFlow> valueFlow_;
  std::unique_ptr<analysis::ValueNumbers> valueNumbers_;
  std::map<const NextStageFacts*, NextStageFacts> stageInputs_;
  // What the module looked like when value flow / value numbers were built: their instruction
  // pointers stay valid exactly while this does.
  size_t indexedShape_ = 0;
  size_t moduleShape() const;
};

}  // namespace stereoshift
