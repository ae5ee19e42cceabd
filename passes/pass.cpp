#include "passes/pass.h"

#include <cctype>
#include <spirv-tools/optimizer.hpp>

namespace stereoshift {

using spirv::Instruction;

const char* toString(PassResult result) {
  switch (result) {
    case PassResult::Unchanged: return "unchanged";
    case PassResult::Changed: return "changed";
    case PassResult::Failed: return "failed";
  }
  return "?";
}

const char* toString(Classification c) {
  switch (c) {
    case Classification::Perspective: return "perspective";
    case Classification::ConstantW1: return "2d-constant-w";
    case Classification::AlreadyStereo: return "already-stereo";
    case Classification::Intermediate: return "intermediate-stage";
    case Classification::NoPositionStage: return "no-position-stage";
    case Classification::NoPositionOutput: return "no-position-output";
  }
  return "?";
}

const char* analysisName(Analysis analysis) {
  switch (analysis) {
    case kClipPositionAnalysis: return "clip-positions";
    case kFoldedCopyAnalysis: return "folded-copy";
  }
  return "?";
}

void PassContext::invalidateAnalyses(AnalysisSet kept) {
  if (!(kept & kClipPositionAnalysis)) clipPositionCache.reset();
  if (!(kept & kFoldedCopyAnalysis)) {
    folded.reset();
    foldTried = false;
  }
}

AnalysisSet PassContext::cachedAnalyses() const {
  return (clipPositionCache ? kClipPositionAnalysis : kNoAnalyses) | (foldTried ? kFoldedCopyAnalysis : kNoAnalyses);
}

const ClipPositionAnalysis& clipPositions(PassContext& context) {
  if (!context.clipPositionCache) {
    context.clipPositionCache.emplace(context.module);
    context.positions = context.clipPositionCache->outputs();
  }
  return *context.clipPositionCache;
}

const spirv::Module* foldedCopy(PassContext& context) {
  if (!context.foldTried) {
    context.foldTried = true;
    spvtools::Optimizer optimizer(SPV_ENV_UNIVERSAL_1_0);
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    // What the analyses need to see through, and no more (SPIRV-Tools' whole performance recipe
    // cost a fifth of a tree conversion; this one about a ninth): every call inlined, private and
    // function variables turned into SSA values, structs and arrays split, constants propagated
    // and folded, duplicate values merged (the matrix chains per-eye-view follows to gl_Position
    // need the last). Chosen by measurement: the shortest list tried that keeps every analysis result
    // of the corpus and the lit tests.
    optimizer.RegisterPassesFromFlags({"--merge-return", "--inline-entry-points-exhaustive", "--private-to-local",
                                       "--scalar-replacement=100", "--eliminate-local-single-block", "--eliminate-local-single-store",
                                       "--eliminate-local-multi-store", "--ccp", "--simplify-instructions",
                                       "--redundancy-elimination"});
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<uint32_t> words = context.module.encode(), folded;
    std::string error;
    if (optimizer.Run(words.data(), words.size(), &folded, options))
      context.folded = spirv::Module::parse(folded, &error);
  }
  return context.folded ? &*context.folded : nullptr;
}

bool carriesEyeParameters(const PassContext& context) {
  bool eyeSign = false, separation = false;
  for (const auto& n : context.module.allNames()) {
    eyeSign |= n == context.options.eye.eyeSignName;
    separation |= n == context.options.eye.separationName;
  }
  return eyeSign && separation;
}

std::string alreadyStereoReason(const PassContext& context) {
  if (carriesEyeParameters(context))
    return "already carries stereo eye parameters ('" + context.options.eye.eyeSignName + "')";
  const spirv::Module& m = context.module;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && m.decorationValue(inst.resultId, spv::DecorationBuiltIn) ==
                                              static_cast<uint32_t>(spv::BuiltInViewIndex))
      return "reads the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID): it is multiview stereo already";
  // glslang 12 reads HLSL's SV_ViewID as a plain input and keeps only its semantic string.
  for (const auto& inst : m.annotations) {
    if (inst.opcode != spv::OpDecorateString || inst.operand(1) != uint32_t(spv::DecorationUserSemantic)) continue;
    std::string semantic = inst.stringOperand(2);
    for (char& c : semantic) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (semantic == "SV_VIEWID" && m.storageClassOf(inst.operand(0)) == spv::StorageClassInput)
      return "reads the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID): it is multiview stereo already";
  }
  return "";
}

bool perClassRegisters(const SourceInfo& source) {
  return source.language == SourceLanguage::Hlsl && !source.vulkanBindings;
}

std::optional<uint32_t> highestBinding(const spirv::Module& m, uint32_t set, bool constantBuffersOnly) {
  std::optional<uint32_t> highest;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    if (constantBuffersOnly && inst.operand(0) != spv::StorageClassUniform) continue;
    auto binding = m.decorationValue(inst.resultId, spv::DecorationBinding);
    if (!binding || m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0) != set) continue;
    highest = std::max(highest.value_or(0), *binding);
  }
  return highest;
}

}  // namespace stereoshift
