#include "passes/pass.h"

#include <glslang/SPIRV/GLSL.std.450.h>
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

bool targetSupportsPrecise(const PassContext& context) {
  TargetLanguage target = context.options.target;
  if (target == TargetLanguage::Auto) {
    switch (context.source.language) {
      case SourceLanguage::Hlsl: return true;
      case SourceLanguage::Spirv: return true;
      case SourceLanguage::Glsl: break;
    }
    int version = context.options.targetVersion.value_or(context.source.version);
    if (context.source.vulkan) return true;
    return context.source.es ? version >= 320 : version >= 400;
  }
  switch (target) {
    case TargetLanguage::Spirv: case TargetLanguage::SpirvAsm: case TargetLanguage::Hlsl: return true;
    case TargetLanguage::Glsl: return context.options.targetVersion.value_or(450) >= 400;
    case TargetLanguage::Essl: return context.options.targetVersion.value_or(310) >= 320;
    default: return false;
  }
}

uint32_t emitLoadEyeParam(PassContext& context, std::vector<Instruction>& out, int which) {
  auto& m = context.module;
  const EyeParams& eye = context.eye;
  uint32_t floatType = m.typeFloat(32);
  switch (eye.source) {
    case EyeSource::SpecConstant:
      return eye.specConstants[which];
    case EyeSource::LooseUniforms: {
      uint32_t value = m.takeId();
      out.emplace_back(spv::OpLoad, floatType, value, std::vector<uint32_t>{eye.looseVariables[which]});
      return value;
    }
    case EyeSource::UniformBlock:
    case EyeSource::PushConstant:
    case EyeSource::Auto: {
      auto storage = eye.source == EyeSource::PushConstant ? spv::StorageClassPushConstant
                                                           : spv::StorageClassUniform;
      uint32_t pointerType = m.typePointer(storage, floatType);
      uint32_t index = m.constantInt(static_cast<int32_t>(eye.firstMember + which));
      uint32_t pointer = m.takeId();
      out.emplace_back(spv::OpAccessChain, pointerType, pointer, std::vector<uint32_t>{eye.variable, index});
      uint32_t value = m.takeId();
      out.emplace_back(spv::OpLoad, floatType, value, std::vector<uint32_t>{pointer});
      return value;
    }
  }
  return 0;
}

uint32_t emitShiftedX(PassContext& context, std::vector<Instruction>& out, uint32_t x, uint32_t w) {
  auto& m = context.module;
  uint32_t f = m.typeFloat(32);
  uint32_t eyeSign = emitLoadEyeParam(context, out, 0);
  uint32_t separation = emitLoadEyeParam(context, out, 1);
  uint32_t convergence = emitLoadEyeParam(context, out, 2);
  bool precise = context.options.invariantPosition && targetSupportsPrecise(context);
  auto op = [&](spv::Op code, uint32_t a, uint32_t b) {
    uint32_t id = m.takeId();
    out.emplace_back(code, f, id, std::vector<uint32_t>{a, b});
    if (precise) m.decorate(id, spv::DecorationNoContraction);
    return id;
  };
  // x + (eyeSign * separation) * (w - convergence): the order of STEREO.md section 1.
  uint32_t depth = op(spv::OpFSub, w, convergence);
  uint32_t scale = op(spv::OpFMul, eyeSign, separation);
  if (context.options.compensatedShift) {
    // x + a*(w - C) correctly rounded up to a hair: w - C exactly as dh + dl (TwoSum), a*dh exactly
    // as ph + pl (TwoProduct), x + ph exactly as sh + sl (TwoSum), then one final rounding of
    // sh + (sl + pl + a*dl). Needs NoContraction honoured (no re-association), so `precise`.
    auto always = [&](spv::Op code, uint32_t a, uint32_t b) {
      uint32_t id = m.takeId();
      out.emplace_back(code, f, id, std::vector<uint32_t>{a, b});
      m.decorate(id, spv::DecorationNoContraction);
      return id;
    };
    uint32_t dh = always(spv::OpFSub, w, convergence);
    uint32_t bb = always(spv::OpFSub, dh, w);
    uint32_t dl = always(spv::OpFSub, always(spv::OpFSub, w, always(spv::OpFSub, dh, bb)),
                         always(spv::OpFAdd, convergence, bb));
    uint32_t a = always(spv::OpFMul, eyeSign, separation);
    uint32_t ph = always(spv::OpFMul, a, dh);
    // The product's rounding error by Dekker's TwoProduct (Veltkamp split, 2^12 + 1): exact without
    // relying on a fused fma, which some drivers (lavapipe among them) evaluate as mul + add.
    uint32_t splitter = m.constantFloat(4097.0f);
    auto split = [&](uint32_t v, uint32_t* hi, uint32_t* lo) {
      uint32_t c = always(spv::OpFMul, splitter, v);
      *hi = always(spv::OpFSub, c, always(spv::OpFSub, c, v));
      *lo = always(spv::OpFSub, v, *hi);
    };
    uint32_t ahi, alo, dhi, dlo;
    split(a, &ahi, &alo);
    split(dh, &dhi, &dlo);
    uint32_t pl = always(spv::OpFAdd,
                         always(spv::OpFAdd, always(spv::OpFAdd, always(spv::OpFSub, always(spv::OpFMul, ahi, dhi), ph),
                                                    always(spv::OpFMul, ahi, dlo)),
                                always(spv::OpFMul, alo, dhi)),
                         always(spv::OpFMul, alo, dlo));
    uint32_t sh = always(spv::OpFAdd, x, ph);
    uint32_t bb2 = always(spv::OpFSub, sh, x);
    uint32_t sl = always(spv::OpFAdd, always(spv::OpFSub, x, always(spv::OpFSub, sh, bb2)),
                         always(spv::OpFSub, ph, bb2));
    uint32_t tail = always(spv::OpFAdd, sl, always(spv::OpFAdd, pl, always(spv::OpFMul, a, dl)));
    return always(spv::OpFAdd, sh, tail);
  }
  if (context.options.fusedShift) {
    // One rounding less: fma(eyeSign * separation, w - convergence, x).
    uint32_t glsl = m.extInstImport("GLSL.std.450");
    uint32_t id = m.takeId();
    out.emplace_back(spv::OpExtInst, f, id, std::vector<uint32_t>{glsl, GLSLstd450Fma, scale, depth, x});
    if (precise) m.decorate(id, spv::DecorationNoContraction);
    return id;
  }
  uint32_t offset = op(spv::OpFMul, scale, depth);
  return op(spv::OpFAdd, x, offset);
}

uint32_t emitCutoffCondition(PassContext& context, std::vector<Instruction>& out, uint32_t w) {
  auto& m = context.module;
  uint32_t boolType = m.typeBool();
  uint32_t f = m.typeFloat(32);
  // eyeSign != 0 first: a mono draw runs none of the shift, so it is the original bit for bit
  // (x + 0 would turn a -0 x into +0).
  uint32_t eyeSign = emitLoadEyeParam(context, out, 0);
  uint32_t stereo = m.takeId();
  out.emplace_back(spv::OpFUnordNotEqual, boolType, stereo, std::vector<uint32_t>{eyeSign, m.constantFloat(0.0f)});
  if (context.options.cutoff == CutoffMode::None) return stereo;

  uint32_t one = m.constantFloat(1.0f);
  // Ordered comparisons: a NaN w is never shifted (no new NaN in x).
  uint32_t far = m.takeId();
  if (context.options.cutoff == CutoffMode::Exact || context.options.cutoffEpsilon <= 0.0f) {
    // The driver's rule: w != 1.
    out.emplace_back(spv::OpFOrdNotEqual, boolType, far, std::vector<uint32_t>{w, one});
  } else {
    uint32_t glsl = m.extInstImport("GLSL.std.450");
    uint32_t diff = m.takeId();
    out.emplace_back(spv::OpFSub, f, diff, std::vector<uint32_t>{w, one});
    uint32_t absDiff = m.takeId();
    out.emplace_back(spv::OpExtInst, f, absDiff, std::vector<uint32_t>{glsl, GLSLstd450FAbs, diff});
    out.emplace_back(spv::OpFOrdGreaterThan, boolType, far,
                     std::vector<uint32_t>{absDiff, m.constantFloat(context.options.cutoffEpsilon)});
  }
  // An infinite w is not shifted either: separation 0 times infinity would be NaN.
  uint32_t infinite = m.takeId();
  out.emplace_back(spv::OpIsInf, boolType, infinite, std::vector<uint32_t>{w});
  uint32_t finite = m.takeId();
  out.emplace_back(spv::OpLogicalNot, boolType, finite, std::vector<uint32_t>{infinite});
  uint32_t farAndFinite = m.takeId();
  out.emplace_back(spv::OpLogicalAnd, boolType, farAndFinite, std::vector<uint32_t>{far, finite});
  uint32_t cond = m.takeId();
  out.emplace_back(spv::OpLogicalAnd, boolType, cond, std::vector<uint32_t>{stereo, farAndFinite});
  return cond;
}

uint32_t emitShiftedVec4Select(PassContext& context, std::vector<Instruction>& out, uint32_t value) {
  auto& m = context.module;
  uint32_t f = m.typeFloat(32);
  uint32_t v4 = m.typeVector(f, 4);
  uint32_t x = m.takeId();
  out.emplace_back(spv::OpCompositeExtract, f, x, std::vector<uint32_t>{value, 0});
  uint32_t w = m.takeId();
  out.emplace_back(spv::OpCompositeExtract, f, w, std::vector<uint32_t>{value, 3});
  uint32_t shifted = emitShiftedX(context, out, x, w);
  if (uint32_t cond = emitCutoffCondition(context, out, w)) {
    uint32_t chosen = m.takeId();
    out.emplace_back(spv::OpSelect, f, chosen, std::vector<uint32_t>{cond, shifted, x});
    shifted = chosen;
  }
  uint32_t result = m.takeId();
  out.emplace_back(spv::OpCompositeInsert, v4, result, std::vector<uint32_t>{shifted, value, 0});
  return result;
}

}  // namespace stereoshift
