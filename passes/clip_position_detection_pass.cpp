// clip-position-detection: turns a module into a classification and the list of its clip-position
// outputs (BuiltIn Position variables, members of gl_PerVertex-style blocks, per-vertex arrays;
// found by the shared clip-position analysis). It changes nothing; later passes act on what it found.
#include "passes/pass.h"
#include "passes/pass_registry.h"
#include "passes/ir/walker.h"

#include <set>

namespace stereoshift {

using spirv::Instruction;

namespace {

bool isFloatConstantOne(const spirv::Module& m, uint32_t id) { return m.floatConstant(id) == 1.0f; }

// Whether `value` (a vec4) provably has w == 1.0 at compile time.
bool hasConstantW1(const spirv::Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (!def) return false;
  if (def->opcode == spv::OpConstantComposite && def->operands.size() == 4)
    return isFloatConstantOne(m, def->operands[3]);
  if (def->opcode == spv::OpCompositeConstruct && !def->operands.empty())
    return isFloatConstantOne(m, def->operands.back());  // last constituent is the scalar w
  return false;
}

class ClipPositionDetectionPass final : public Pass {
 public:
  const char* name() const override { return "clip-position-detection"; }

  PassResult run(PassContext& ctx) override {
    auto& m = ctx.module;
    DetectionFacts& facts = ctx.record.detection;
    spv::ExecutionModel model = m.executionModel();
    const ClipPositionAnalysis& positions = ctx.analyses.clipPositions();
    facts.positions.clear();
    for (const auto& p : positions.outputs()) facts.positions.push_back(p.description);

    bool preRaster = model == spv::ExecutionModelVertex || model == spv::ExecutionModelTessellationEvaluation ||
                     model == spv::ExecutionModelGeometry || model == spv::ExecutionModelMeshEXT ||
                     model == spv::ExecutionModelMeshNV;
    if (!preRaster) {
      ctx.classification = Classification::NoPositionStage;
    } else if (!ctx.options.shiftThisStage) {
      ctx.classification = Classification::Intermediate;
    } else if (positions.outputs().empty()) {
      ctx.classification = Classification::NoPositionOutput;
    } else if (model == spv::ExecutionModelGeometry && !emitsAVertex(m)) {
      // Nothing it writes reaches the rasterizer (a link-only test, a stage kept for its side
      // effects): the shift would have no site, and eye parameters nothing would read.
      ctx.classification = Classification::NoVertexEmitted;
      ctx.diags.note(ctx.file, "geometry shader emits no vertex: it rasterizes nothing, so nothing is shifted");
    } else if (std::string why = alreadyStereoReason(ctx); !why.empty()) {
      ctx.classification = Classification::AlreadyStereo;
      facts.alreadyStereo = why;
      ctx.diags.note(ctx.file, "shader " + why + "; left as it is, never shifted twice");
    } else if (allWritesHaveConstantW1(ctx.module, positions) ||
               (!entryStoresRuntimeProduct(ctx.module, positions) && constantW1AfterFolding(ctx))) {
      ctx.classification = Classification::ConstantW1;
    } else {
      ctx.classification = Classification::Perspective;
      ctx.shiftPosition = true;  // with --corrections-only for the halo copies: stereo-shift leaves it
      if (ctx.options.correctionsOnly) {
        facts.leftToDriver = true;
        ctx.diags.note(ctx.file, "--corrections-only: the clip position is left to the driver's own shift");
      }
    }
    facts.classification = ctx.classification;
    return PassResult::Unchanged;
  }

 private:
  static bool emitsAVertex(const spirv::Module& m) {
    bool emits = false;
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      emits |= inst.opcode == spv::OpEmitVertex || inst.opcode == spv::OpEmitStreamVertex;
    });
    return emits;
  }

  // Cheap proof of a perspective position, which spares most vertex shaders the folded copy (an
  // optimizer run): the entry function itself stores `M * v` (or `v * M`, M possibly `A * B`) to the
  // position, with M loaded from a uniform, push-constant, storage or input variable. Inlining and
  // folding keep that store, and no folding can turn a product with a matrix known only at run time
  // into the constant 1, so the folded copy could never prove w = 1.
  static bool entryStoresRuntimeProduct(const spirv::Module& m, const ClipPositionAnalysis& positions) {
    auto runtimeMatrix = [&](uint32_t id, auto& self) -> bool {
      const Instruction* def = m.definition(id);
      if (!def) return false;
      if (def->opcode == spv::OpMatrixTimesMatrix)
        return self(def->operand(0), self) && self(def->operand(1), self);
      if (def->opcode != spv::OpLoad) return false;
      auto storage = m.storageClassOf(def->operand(0));
      return storage && (*storage == spv::StorageClassUniform || *storage == spv::StorageClassUniformConstant ||
                         *storage == spv::StorageClassPushConstant || *storage == spv::StorageClassStorageBuffer ||
                         *storage == spv::StorageClassInput);
    };
    auto isPosition = [&](uint32_t pointer) {
      for (size_t i = 0; i < positions.outputs().size(); ++i)
        if (!positions.outputs()[i].arrayed && positions.wholePointers(i).count(pointer)) return true;
      return false;
    };
    for (const auto& fn : m.functions) {
      if (fn.id() != m.entryFunctionId()) continue;
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions) {
          if (inst.opcode != spv::OpStore || !isPosition(inst.operand(0))) continue;
          const Instruction* value = m.definition(inst.operand(1));
          if (!value) continue;
          if (value->opcode == spv::OpMatrixTimesVector && runtimeMatrix(value->operand(0), runtimeMatrix)) return true;
          if (value->opcode == spv::OpVectorTimesMatrix && runtimeMatrix(value->operand(1), runtimeMatrix)) return true;
        }
    }
    return false;
  }

  // The literal w = 1.0 may only show after inlining and folding (HLSL output structs, helper
  // functions): ask the shared folded copy.
  static bool constantW1AfterFolding(PassContext& ctx) {
    const spirv::Module* folded = ctx.analyses.foldedCopy();
    if (!folded) return false;
    ClipPositionAnalysis positions(*folded);
    return !positions.outputs().empty() && allWritesHaveConstantW1(*folded, positions);
  }

  // True when every write of every clip position stores a vector whose w is the literal 1.0.
  static bool allWritesHaveConstantW1(const spirv::Module& m, const ClipPositionAnalysis& analysis) {
    bool sawStore = false;
    for (size_t output = 0; output < analysis.outputs().size(); ++output) {
      const ClipPosition& position = analysis.outputs()[output];
      if (position.arrayed) return false;
      // Pointers to the whole position: the variable itself, or chains to the position member.
      const std::set<uint32_t>& pointers = analysis.wholePointers(output);
      for (const auto& fn : m.functions)
        for (const auto& block : fn.blocks)
          for (const auto& inst : block.instructions) {
            if (inst.opcode == spv::OpLoad) continue;
            if (position.isMember && pointers.count(inst.resultId)) continue;
            if (position.isMember && (inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain) &&
                inst.operand(0) == position.variable && inst.operands.size() > 2) {
              const Instruction* index = m.definition(inst.operand(1));
              if (!index || index->opcode != spv::OpConstant || index->operand(0) == position.member) return false;
            }
            bool usesPointer = false;
            for (uint32_t operand : inst.operands) usesPointer |= pointers.count(operand) > 0;
            // The whole block written at once (e.g. a struct copy) is not provable either.
            if (position.isMember && inst.opcode != spv::OpAccessChain && inst.opcode != spv::OpInBoundsAccessChain)
              for (uint32_t operand : inst.operands) usesPointer |= operand == position.variable;
            if (!usesPointer) continue;
            if (inst.opcode != spv::OpStore || !hasConstantW1(m, inst.operand(1))) return false;
            sawStore = true;
          }
    }
    return sawStore;
  }
};

}  // namespace

std::unique_ptr<Pass> createClipPositionDetectionPass() { return std::make_unique<ClipPositionDetectionPass>(); }

PassInfo clipPositionDetectionPassInfo() {
  return {"clip-position-detection", createClipPositionDetectionPass,
          "classifies the shader (perspective, 2D, already stereo, ...) and finds its clip-position outputs",
          "always",
          "analysis only, first: every geometry pass below does nothing unless it found a perspective last stage",
          {}, kClipPositionAnalysis | kFoldedCopyAnalysis, kAllAnalyses, kNoEdits};
}

}  // namespace stereoshift
