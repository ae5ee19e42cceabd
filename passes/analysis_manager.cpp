// See analysis_manager.h.
#include "passes/analysis_manager.h"

#include "passes/analysis/stage_interface.h"
#include "core/crash_phase.h"

#include <spirv-tools/optimizer.hpp>

#include <functional>
#include <map>
#include <set>

namespace stereoshift {

const char* analysisName(Analysis analysis) {
  switch (analysis) {
    case kClipPositionAnalysis: return "clip-positions";
    case kFoldedCopyAnalysis: return "folded-copy";
    case kValueFlowAnalysis: return "value-flow";
    case kValueNumberAnalysis: return "value-numbers";
    case kStageInputAnalysis: return "stage-input-uses";
  }
  return "?";
}

AnalysisManager::AnalysisManager(const spirv::Module& module, const SourceInfo& source, std::string file,
                                 bool foldedCopy)
    : module_(module), source_(source), file_(std::move(file)), foldingAllowed_(foldedCopy) {}

AnalysisManager::~AnalysisManager() = default;

const ClipPositionAnalysis& AnalysisManager::clipPositions() {
  if (!clipPositions_) clipPositions_.emplace(module_);
  return *clipPositions_;
}

namespace {

bool runOptimizer(const std::vector<std::string>& flags, const std::vector<uint32_t>& in, std::vector<uint32_t>* out) {
  spvtools::Optimizer optimizer(SPV_ENV_UNIVERSAL_1_0);
  optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
  if (!optimizer.RegisterPassesFromFlags(flags)) return false;
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);
  return optimizer.Run(in.data(), in.size(), out, options);
}

// Removes the functions no entry point reaches through calls (after exhaustive inlining: every
// helper), with the names and decorations of what they define. Linear, unlike SPIRV-Tools' own
// dead-function pass, which kills one instruction at a time through its def-use sets.
void dropUnreachableFunctions(spirv::Module& module) {
  std::set<uint32_t> reached;
  std::vector<uint32_t> work;
  for (const auto& entry : module.entryPoints) work.push_back(entry.operand(1));
  std::map<uint32_t, const spirv::Function*> byId;
  for (const auto& fn : module.functions) byId[fn.id()] = &fn;
  while (!work.empty()) {
    uint32_t id = work.back();
    work.pop_back();
    if (!reached.insert(id).second || !byId.count(id)) continue;
    for (const auto& block : byId[id]->blocks)
      for (const auto& inst : block.instructions)
        if (inst.opcode == spv::OpFunctionCall) work.push_back(inst.operand(0));
  }
  std::set<uint32_t> removedIds;
  std::vector<spirv::Function> kept;
  for (auto& fn : module.functions) {
    if (reached.count(fn.id())) {
      kept.push_back(std::move(fn));
      continue;
    }
    removedIds.insert(fn.id());
    for (const auto& parameter : fn.parameters) removedIds.insert(parameter.resultId);
    for (const auto& block : fn.blocks) {
      removedIds.insert(block.labelId);
      for (const auto& inst : block.instructions)
        if (inst.resultId) removedIds.insert(inst.resultId);
    }
  }
  module.functions = std::move(kept);
  if (removedIds.empty()) return;
  module.forgetIds(removedIds);
  module.invalidateDefinitions();
}

// `accessChains`: constant-index access chains into function variables (a vector's components,
// as decompiled HLSL writes its registers: `r0.xy = ...`) turned into loads, inserts and stores
// first, so those variables become SSA values too (the register copy of registerSsaCopy()).
std::optional<spirv::Module> makeFoldedCopy(const spirv::Module& module, bool accessChains = false) {
  ScopedCrashPhase phase(kFoldedCopyPhase);
  // What the analyses need to see through, and no more (SPIRV-Tools' whole performance recipe
  // cost a fifth of a tree conversion; this one about a ninth): every call inlined, private and
  // function variables turned into SSA values, structs and arrays split, constants propagated
  // and folded, duplicate values merged (the matrix chains per-eye-view follows to gl_Position
  // need the last). Chosen by measurement: the shortest list tried that keeps every analysis result
  // of the corpus and the lit tests.
  //
  // In two runs, with the helpers inlining left dead removed between them: HLSL's entry point is a
  // helper its wrapper calls, and the copy of it left beside the inlined one made the SSA rewrite
  // quadratic in its statements (SPIRV-Tools checks every use of a variable once per use where a
  // store to it survives the single-block pass): 6,000 statements took 5 s, 30,000 over a minute.
  std::vector<uint32_t> inlined, folded;
  std::string error;
  if (!runOptimizer({"--merge-return", "--inline-entry-points-exhaustive"}, module.encode(), &inlined)) return std::nullopt;
  auto reduced = spirv::Module::parse(inlined, &error);
  if (!reduced) return std::nullopt;
  dropUnreachableFunctions(*reduced);
  std::vector<std::string> flags = {"--private-to-local", "--scalar-replacement=100"};
  if (accessChains) flags.push_back("--convert-local-access-chains");
  flags.push_back("--eliminate-local-single-block");
  // The register copy: a register read in a condition before a branch (`if (r1.x >= 1) discard;`,
  // a sky's early out) leaves an access chain into it that the single-block pass makes dead, and a
  // variable with any access chain is never made SSA values, so every later read of the register
  // saw every write to it. Dead code removed first.
  if (accessChains) flags.push_back("--eliminate-dead-code-aggressive");
  for (const char* flag : {"--eliminate-local-single-store", "--eliminate-local-multi-store", "--ccp",
                           "--simplify-instructions", "--redundancy-elimination"})
    flags.push_back(flag);
  if (!runOptimizer(flags, reduced->encode(), &folded))
    return std::nullopt;
  return spirv::Module::parse(folded, &error);
}

}  // namespace

const spirv::Module* AnalysisManager::foldedCopy() {
  if (!foldTried_) {
    foldTried_ = true;
    if (foldingAllowed_) folded_ = makeFoldedCopy(module_);
  }
  return folded_ ? &*folded_ : nullptr;
}

const spirv::Module* AnalysisManager::registerSsaCopy() {
  if (!registerTried_) {
    registerTried_ = true;
    if (foldingAllowed_) registers_ = makeFoldedCopy(module_, true);
  }
  return registers_ ? &*registers_ : nullptr;
}

analysis::ViewVectorFlow* AnalysisManager::foldedViewVectorFlow() {
  const spirv::Module* folded = foldedCopy();
  if (!folded) return nullptr;
  if (!foldedFlow_) foldedFlow_ = std::make_unique<analysis::ViewVectorFlow>(*folded);
  return foldedFlow_.get();
}

const analysis::ValueFlow& AnalysisManager::valueFlow() {
  if (!valueFlow_) {
    valueFlow_ = std::make_unique<analysis::ValueFlow>(module_);
    indexedShape_ = moduleShape();
  }
  return *valueFlow_;
}

const analysis::ValueNumbers& AnalysisManager::valueNumbers() {
  if (!valueNumbers_) {
    valueNumbers_ = std::make_unique<analysis::ValueNumbers>(module_);
    indexedShape_ = moduleShape();
  }
  return *valueNumbers_;
}

const NextStageFacts& AnalysisManager::stageInputUses(const NextStageFacts* consumer) {
  auto found = stageInputs_.find(consumer);
  if (found != stageInputs_.end()) return found->second;
  const spirv::Module* folded = foldedCopy();
  NextStageFacts facts =
      analysis::describeStageInputUses(module_, folded, foldedViewVectorFlow(), source_, file_, consumer);
  return stageInputs_.emplace(consumer, std::move(facts)).first->second;
}

void AnalysisManager::invalidate(AnalysisSet kept) {
  if (!(kept & kClipPositionAnalysis)) clipPositions_.reset();
  if (!(kept & kFoldedCopyAnalysis)) {
    foldedFlow_.reset();  // built on the copy
    folded_.reset();
    foldTried_ = false;
    registers_.reset();
    registerTried_ = false;
  }
  if (!(kept & kValueFlowAnalysis)) valueFlow_.reset();
  if (!(kept & kValueNumberAnalysis)) valueNumbers_.reset();
  if (!(kept & kStageInputAnalysis)) stageInputs_.clear();
}

AnalysisSet AnalysisManager::cached() const {
  AnalysisSet set = kNoAnalyses;
  if (clipPositions_) set |= kClipPositionAnalysis;
  if (foldTried_ || registerTried_) set |= kFoldedCopyAnalysis;
  if (valueFlow_) set |= kValueFlowAnalysis;
  if (valueNumbers_) set |= kValueNumberAnalysis;
  if (!stageInputs_.empty()) set |= kStageInputAnalysis;
  return set;
}

// Where every instruction of the module lives and how many there are: value flow and value
// numbers hold pointers into these vectors, valid exactly while none of them moved or changed size.
size_t AnalysisManager::moduleShape() const {
  size_t shape = 0;
  auto mix = [&](const void* data, size_t size) {
    shape = shape * 1000003u ^ std::hash<const void*>()(data);
    shape = shape * 1000003u ^ size;
  };
  for (const auto* section : {&module_.capabilities, &module_.extensions, &module_.extInstImports,
                              &module_.memoryModel, &module_.entryPoints, &module_.executionModes,
                              &module_.debugSource, &module_.debugNames, &module_.debugModuleProcessed,
                              &module_.annotations, &module_.typesValues})
    mix(section->data(), section->size());
  mix(module_.functions.data(), module_.functions.size());
  for (const auto& fn : module_.functions) {
    mix(fn.blocks.data(), fn.blocks.size());
    for (const auto& block : fn.blocks) mix(block.instructions.data(), block.instructions.size());
  }
  return shape;
}

std::string AnalysisManager::checkPreserved(AnalysisSet claimed) {
  if ((claimed & kClipPositionAnalysis) && clipPositions_ && !(*clipPositions_ == ClipPositionAnalysis(module_)))
    return analysisName(kClipPositionAnalysis);
  if ((claimed & kFoldedCopyAnalysis) && folded_) {
    // The copy's globals are the module's own: each must still be there, as the same kind of value.
    for (const auto& inst : folded_->typesValues) {
      if (inst.opcode != spv::OpVariable) continue;
      const spirv::Instruction* now = module_.definition(inst.resultId);
      if (!now || now->opcode != spv::OpVariable || now->typeId != inst.typeId) return analysisName(kFoldedCopyAnalysis);
    }
  }
  if ((claimed & (kValueFlowAnalysis | kValueNumberAnalysis)) && (valueFlow_ || valueNumbers_) &&
      moduleShape() != indexedShape_)
    return analysisName(valueFlow_ && (claimed & kValueFlowAnalysis) ? kValueFlowAnalysis : kValueNumberAnalysis);
  if ((claimed & kStageInputAnalysis) && !stageInputs_.empty()) {
    AnalysisManager fresh(module_, source_, file_);
    for (const auto& [consumer, facts] : stageInputs_)
      if (!(fresh.stageInputUses(consumer) == facts)) return analysisName(kStageInputAnalysis);
  }
  return "";
}

}  // namespace stereoshift
