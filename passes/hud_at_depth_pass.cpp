// hud-at-depth: turns a proven-2D shader (every clip position written with the literal w = 1) into
// one that places its element at the eye depth `hudDepth`: each store of the position `pos` becomes
// a store of `pos * hudDepth`, i.e. vec4(pos.xy * d, pos.z * d, d) (docs/stereo-math.md section 2). The shader
// then needs the shift like any perspective position, which gives the element the parallax
// e*S*(1 - C/d). Opt-in (--hud-at-depth): without it 2D shaders stay mono and are copied through.
//
// Why z becomes z*d (and not z as in the plain formula): with w = d the rasterizer divides every
// component by d, so z*d keeps the element's NDC depth (its depth-buffer value and clipping) exactly
// what the mono shader wrote; the depth test keeps deciding the same way whatever d the application
// picks. A z left as is would land at z/d: a HUD written at the near plane would slide into the
// scene and be hidden by it. Because every vertex gets the same w = d, perspective-correct
// interpolation of the varyings equals the original linear one, and x/w, y/w are the original x, y:
// in mono the element covers the very same pixels.
#include "passes/eye_param_emitter.h"
#include "passes/ir/builder.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"
#include "passes/shift_emitter.h"

#include <algorithm>
#include <set>

namespace stereoshift {

using spirv::Instruction;

namespace {

class HudAtDepthPass final : public Pass {
 public:
  const char* name() const override { return "hud-at-depth"; }

  PassResult run(PassContext& ctx) override {
    if (!ctx.options.hudAtDepth || !ctx.options.shiftThisStage || ctx.classification != Classification::ConstantW1)
      return PassResult::Unchanged;
    auto& m = ctx.module;
    HudAtDepthFacts& facts = ctx.record.hudAtDepth;

    // Whole-vector stores of each position, and whether anything else writes it. The proof of
    // w = 1 may come from the folded copy (helpers, HLSL structs); the real module's stores must
    // still be whole vec4 stores so that `pos * d` gives w = d.
    struct Site {
      spirv::Block* block;
      size_t index;
    };
    std::vector<Site> sites;
    std::vector<std::string> placed;
    const ClipPositionAnalysis& positions = ctx.analyses.clipPositions();
    for (size_t output = 0; output < positions.outputs().size(); ++output) {
      const ClipPosition& position = positions.outputs()[output];
      if (position.arrayed) return leaveAlone(ctx, "per-vertex position arrays");
      const std::set<uint32_t>& wholePointers = positions.wholePointers(output);
      const std::set<uint32_t>& partialPointers = positions.componentPointers(output);
      for (auto& fn : m.functions)
        for (auto& block : fn.blocks)
          for (size_t i = 0; i < block.instructions.size(); ++i) {
            const Instruction& inst = block.instructions[i];
            if (inst.opcode == spv::OpStore && partialPointers.count(inst.operand(0)))
              return leaveAlone(ctx, "the position is written one component at a time");
            if (inst.opcode == spv::OpCopyMemory && (wholePointers.count(inst.operand(0)) || partialPointers.count(inst.operand(0))))
              return leaveAlone(ctx, "the position is written by a memory copy");
            if (inst.opcode == spv::OpStore && wholePointers.count(inst.operand(0))) sites.push_back({&block, i});
          }
      placed.push_back(position.description);
    }
    if (sites.empty()) return leaveAlone(ctx, "no store of the position found");

    if (!ensureEyeParams(ctx, kHudDepth + 1)) return PassResult::Failed;
    uint32_t v4 = m.typeVector(m.typeFloat(32), 4);
    // Back to front within a block so the recorded indices stay valid while code is inserted.
    std::sort(sites.begin(), sites.end(), [](const Site& a, const Site& b) {
      return a.block != b.block ? a.block < b.block : a.index < b.index;
    });
    for (size_t s = sites.size(); s-- > 0;) {
      auto& instructions = sites[s].block->instructions;
      size_t at = sites[s].index;
      std::vector<Instruction> code;
      uint32_t depth = emitLoadEyeParam(ctx, code, kHudDepth);
      // w is the literal 1, so one multiply gives (x*d, y*d, z*d, d) with w exactly d.
      uint32_t placedValue =
          spirv::Builder(m, code).add(spv::OpVectorTimesScalar, v4, {instructions[at].operand(1), depth});
      instructions[at].operands[1] = placedValue;
      instructions.insert(instructions.begin() + static_cast<long>(at), code.begin(), code.end());
    }
    m.invalidateDefinitions();

    // From here on the position is a perspective one: eye-params, halo and stereo-shift treat it so.
    ctx.shiftPosition = true;
    facts.placedAtDepth = placed;
    facts.stores = sites.size();
    facts.position = "vec4(pos.xy * " + ctx.eye.names[kHudDepth] + ", pos.z * " + ctx.eye.names[kHudDepth] +
                         ", " + ctx.eye.names[kHudDepth] + ")";
    if (ctx.options.cutoff != CutoffMode::None)
      facts.note = "the w != 1 cutoff also applies here: a " + ctx.eye.names[kHudDepth] +
                       " within the cutoff epsilon of 1 leaves the element unshifted (use --no-cutoff "
                       "to give it parallax at depth 1 too)";
    return PassResult::Changed;
  }

 private:
  PassResult leaveAlone(PassContext& ctx, const std::string& why) {
    ctx.diags.warning(ctx.file, "--hud-at-depth: not placed at depth: " + why);
    ctx.record.hudAtDepth.leftAlone = why;
    return PassResult::Unchanged;
  }
};

}  // namespace

std::unique_ptr<Pass> createHudAtDepthPass() { return std::make_unique<HudAtDepthPass>(); }

// Placing at depth scales the stored position; the folded copy still answers what later passes
// ask of it (which outputs copy the position the application computed), so it is kept.
PassInfo hudAtDepthPassInfo() {
  return {"hud-at-depth", createHudAtDepthPass,
          "places a proven-2D shader (w = 1) at the eye depth hudDepth, so it gets the shift",
          "--hud-at-depth (off by default)",
          "turns a 2D position into one at depth, which then needs the shift like any perspective position: "
          "before eye-params, halo and stereo-shift",
          {"clip-position-detection"}, kClipPositionAnalysis, kFoldedCopyAnalysis,
          editSet(EditKind::PositionAtDepth)};
}

}  // namespace stereoshift
