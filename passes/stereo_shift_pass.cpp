// stereo-shift: turns the last pre-rasterization stage's clip position into the per-eye one,
// `if (abs(w - 1) > eps) x += eyeSign * separation * (w - convergence)`, applied where the
// position is final: before every return of a vertex / tessellation-evaluation entry point, and
// before every EmitVertex / EmitStreamVertex of a geometry shader (in any function). A mesh shader
// has no such point (each invocation writes any vertices of the per-vertex output array, in any
// order): there the value of every store of a whole clip position is shifted instead.
#include "passes/eye_select.h"  // outputLanguage, glslOutputVersion
#include "passes/ir/builder.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"
#include "passes/shift_emitter.h"

#include <optional>

namespace stereoshift {

using spirv::Block;
using spirv::Builder;
using spirv::Instruction;

namespace {

class StereoShiftPass final : public Pass {
 public:
  const char* name() const override { return "stereo-shift"; }

  PassResult run(PassContext& ctx) override {
    // --corrections-only: the driver shifts the position itself (its halo copies are halo's).
    if (!ctx.shiftPosition || ctx.options.correctionsOnly) return PassResult::Unchanged;
    auto& m = ctx.module;
    ShiftFacts& facts = ctx.record.shift;
    const std::vector<ClipPosition>& positions = ctx.analyses.clipPositions().outputs();
    if (!ctx.eyeDeclared) {
      ctx.diags.error(ctx.file, "stereo-shift needs the eye-params pass to run first");
      return PassResult::Failed;
    }
    spv::ExecutionModel model = m.executionModel();
    if (model == spv::ExecutionModelMeshEXT || model == spv::ExecutionModelMeshNV) return shiftMeshStores(ctx, facts);
    for (const auto& p : positions)
      if (p.arrayed) {
        ctx.diags.error(ctx.file, "per-vertex clip-position arrays are not supported in this stage");
        return PassResult::Failed;
      }

    bool geometry = model == spv::ExecutionModelGeometry;
    int sites = 0;
    for (auto& fn : m.functions) {
      if (!geometry && fn.id() != m.entryFunctionId()) continue;
      for (size_t bi = 0; bi < fn.blocks.size(); ++bi) {
        size_t start = 0;
        while (true) {
          Block& block = fn.blocks[bi];
          size_t at = findSite(block, start, geometry);
          if (at == block.instructions.size()) break;
          bool split = insertShift(ctx, fn, bi, at);
          ++sites;
          if (split) {
            bi += 2;    // then-block, then the rest block which starts with the site itself
            start = 1;
          } else {
            start = at + 1 + insertedCount_;
          }
        }
      }
    }
    // GLSL 1.10 has no `invariant` (1.20 brought it; every ESSL has it): there the position stays as
    // it is, or the output would not compile.
    const TargetLanguage target = outputLanguage(ctx);
    const bool invariantExists = target != TargetLanguage::Glsl || glslOutputVersion(ctx, target) >= 120;
    if (ctx.options.invariantPosition && invariantExists)
      for (const auto& p : positions) {
        if (p.isMember)
          m.decorateMember(m.pointeeType(m.definition(p.variable)->typeId), p.member, spv::DecorationInvariant);
        else
          m.decorate(p.variable, spv::DecorationInvariant);
      }
    m.invalidateDefinitions();
    facts.sites = sites;
    facts.form = ctx.options.shiftForm == ShiftForm::Branch ? "branch" : "select";
    if (sites == 0) {
      ctx.diags.warning(ctx.file, geometry ? "geometry shader emits no vertex: nothing shifted"
                                           : "entry point has no return: nothing shifted");
      return PassResult::Unchanged;
    }
    return PassResult::Changed;
  }

 private:
  size_t insertedCount_ = 0;

  // The indices a pointer applies to its root variable, through nested access chains; nullopt
  // when one of them is not a constant where it selects a struct member (checked by the caller).
  static std::vector<uint32_t> chainIndices(const spirv::Module& m, uint32_t pointer) {
    std::vector<uint32_t> indices;
    for (const Instruction* def = m.definition(pointer);
         def && (def->opcode == spv::OpAccessChain || def->opcode == spv::OpInBoundsAccessChain);
         def = m.definition(def->operand(0)))
      indices.insert(indices.begin(), def->operands.begin() + 1, def->operands.end());
    return indices;
  }

  // What an access into per-vertex output `p` reaches: the whole position of one vertex, part of
  // it, something that contains it (a whole vertex or the whole array), or another member.
  enum class Reach { WholePosition, PartOfPosition, ContainsPosition, Other };
  static Reach reachOf(const spirv::Module& m, const ClipPosition& p, uint32_t pointer) {
    std::vector<uint32_t> indices = chainIndices(m, pointer);
    size_t positionDepth = p.isMember ? 2 : 1;  // [vertex, member] or [vertex]
    if (indices.size() < positionDepth) return Reach::ContainsPosition;
    if (p.isMember) {
      const Instruction* member = m.definition(indices[1]);
      if (!member || member->opcode != spv::OpConstant) return Reach::PartOfPosition;  // unknown: be safe
      if (member->operand(0) != p.member) return Reach::Other;
    }
    return indices.size() == positionDepth ? Reach::WholePosition : Reach::PartOfPosition;
  }

  // Mesh shaders: every OpStore of a whole vertex position gets the shifted value (the cutoff and
  // the eye guard in select form, as the other per-value shifts). A shader that reads a position
  // back, writes part of one, or moves whole vertices is refused: a read-back would see (and a
  // later store would shift again) the shifted value.
  PassResult shiftMeshStores(PassContext& ctx, ShiftFacts& facts) {
    auto& m = ctx.module;
    const std::vector<ClipPosition>& positions = ctx.analyses.clipPositions().outputs();
    int sites = 0;
    auto refuse = [&](const std::string& why) {
      ctx.diags.error(ctx.file, "mesh shader " + why + ": only stores of whole vertex positions "
                                "(gl_MeshVerticesEXT[i].gl_Position = v) can be shifted");
      return PassResult::Failed;
    };
    for (auto& fn : m.functions)
      for (auto& block : fn.blocks)
        for (size_t i = 0; i < block.instructions.size(); ++i) {
          const Instruction inst = block.instructions[i];
          for (const auto& p : positions) {
            auto rootedHere = [&](uint32_t pointer) { return m.rootVariable(pointer) == p.variable || pointer == p.variable; };
            switch (inst.opcode) {
              case spv::OpStore: {
                if (!rootedHere(inst.operand(0))) break;
                Reach reach = reachOf(m, p, inst.operand(0));
                if (reach == Reach::Other) break;
                if (reach == Reach::PartOfPosition) return refuse("writes part of a vertex position (" + p.description + ")");
                if (reach == Reach::ContainsPosition) return refuse("stores whole vertices or the whole vertex array");
                std::vector<Instruction> code;
                uint32_t shifted = emitShiftedVec4Select(ctx, code, inst.operand(1));
                block.instructions[i].operands[1] = shifted;
                block.instructions.insert(block.instructions.begin() + static_cast<long>(i), code.begin(), code.end());
                i += code.size();
                m.invalidateDefinitions();
                ++sites;
                break;
              }
              case spv::OpLoad:
                if (rootedHere(inst.operand(0)) && reachOf(m, p, inst.operand(0)) != Reach::Other)
                  return refuse("reads back a vertex position it wrote (" + p.description + ")");
                break;
              case spv::OpCopyMemory:
              case spv::OpCopyMemorySized:
                if (rootedHere(inst.operand(0)) || rootedHere(inst.operand(1))) return refuse("copies vertex memory");
                break;
              case spv::OpFunctionCall:
                for (size_t k = 1; k < inst.operands.size(); ++k)
                  if (rootedHere(inst.operands[k])) return refuse("passes the vertex array to a function");
                break;
              default: break;
            }
          }
        }
    m.invalidateDefinitions();
    facts.sites = sites;
    facts.form = "select";
    if (sites == 0) {
      ctx.diags.warning(ctx.file, "mesh shader writes no vertex position: nothing shifted");
      return PassResult::Unchanged;
    }
    return PassResult::Changed;
  }

  static size_t findSite(const Block& block, size_t start, bool geometry) {
    for (size_t i = start; i < block.instructions.size(); ++i) {
      spv::Op op = block.instructions[i].opcode;
      if (geometry ? (op == spv::OpEmitVertex || op == spv::OpEmitStreamVertex) : op == spv::OpReturn) return i;
    }
    return block.instructions.size();
  }

  // Inserts the shift before instruction `at` of block `bi`. Returns true when the block was split
  // into [head | then | rest]; false when the code went inline (select form, loop header).
  bool insertShift(PassContext& ctx, spirv::Function& fn, size_t bi, size_t at) {
    auto& m = ctx.module;
    const std::vector<ClipPosition>& positions = ctx.analyses.clipPositions().outputs();
    uint32_t f = m.typeFloat(32);
    uint32_t v4 = m.typeVector(f, 4);
    bool loopHeader = fn.blocks[bi].mergeInstruction() &&
                      fn.blocks[bi].mergeInstruction()->opcode == spv::OpLoopMerge;
    bool branch = ctx.options.shiftForm == ShiftForm::Branch &&
                  !loopHeader;

    if (!branch) {
      std::vector<Instruction> code;
      Builder b(m, code);
      for (const auto& p : positions) {
        uint32_t pointer = positionPointer(ctx, code, p, v4);
        uint32_t value = b.load(v4, pointer);
        b.store(pointer, emitShiftedVec4Select(ctx, code, value));
      }
      auto& insts = fn.blocks[bi].instructions;
      insts.insert(insts.begin() + static_cast<long>(at), code.begin(), code.end());
      insertedCount_ = code.size();
      m.invalidateDefinitions();
      return false;
    }

    // head: load the position and test the cutoff; then: store the shifted x; rest: the site onward
    // (its successors' phis now name it).
    const uint32_t restLabel = m.takeId();
    spirv::splitBlock(m, fn, bi, at, restLabel);
    Block then{m.takeId(), {}};

    // Several clip positions are exotic; each gets its own guard inside the single then-block.
    std::vector<Instruction>& headCode = fn.blocks[bi].instructions;
    Builder b(m, headCode, true);
    const auto& p = positions.front();
    uint32_t pointer = positionPointer(ctx, headCode, p, v4);
    uint32_t value = b.load(v4, pointer);
    uint32_t w = b.extract(f, value, 3);
    uint32_t cond = emitCutoffCondition(ctx, headCode, w);
    b.addVoid(spv::OpSelectionMerge, {restLabel, 0});
    b.addVoid(spv::OpBranchConditional, {cond, then.labelId, restLabel});

    b.appendTo(then.instructions);
    uint32_t x = b.extract(f, value, 0);
    uint32_t shiftedX = emitShiftedX(ctx, then.instructions, x, w);
    uint32_t xPointer = b.reserveId();
    std::vector<uint32_t> chain = {p.variable};
    if (p.isMember) chain.push_back(m.constantInt(static_cast<int32_t>(p.member)));
    chain.push_back(m.constantInt(0));
    b.addAs(xPointer, spv::OpAccessChain, m.typePointer(spv::StorageClassOutput, f), chain);
    b.store(xPointer, shiftedX);
    for (size_t i = 1; i < positions.size(); ++i) {  // further positions: branch-free
      const auto& extra = positions[i];
      uint32_t extraPointer = positionPointer(ctx, then.instructions, extra, v4);
      uint32_t extraValue = b.load(v4, extraPointer);
      b.store(extraPointer, emitShiftedVec4Select(ctx, then.instructions, extraValue));
    }
    b.branch(restLabel);
    fn.blocks.insert(fn.blocks.begin() + static_cast<long>(bi) + 1, std::move(then));
    m.invalidateDefinitions();
    return true;
  }

  static uint32_t positionPointer(PassContext& ctx, std::vector<Instruction>& out, const ClipPosition& p, uint32_t v4) {
    if (!p.isMember) return p.variable;
    auto& m = ctx.module;
    Builder b(m, out);
    uint32_t pointer = b.reserveId();
    return b.addAs(pointer, spv::OpAccessChain, m.typePointer(spv::StorageClassOutput, v4),
                   {p.variable, m.constantInt(static_cast<int32_t>(p.member))});
  }
};

}  // namespace

std::unique_ptr<Pass> createStereoShiftPass() { return std::make_unique<StereoShiftPass>(); }

// Loads the position and adds chains to it: new pointers and values, the analysis is stale.
PassInfo stereoShiftPassInfo() {
  return {"stereo-shift", createStereoShiftPass,
          "shifts the final clip position by eyeSign*separation*(w - convergence) at every return / emit",
          "always (--shift-form, --no-cutoff, --fused-shift, --compensated-shift: how)",
          "after halo; it guards and shifts the position where it is final",
          {"clip-position-detection", "eye-params"}, kClipPositionAnalysis, kFoldedCopyAnalysis,
          editSet(EditKind::PositionShift)};
}

}  // namespace stereoshift
