// deferred-unprojection's re-projections: turns `clip = VP * (p, 1)` over cbuffer rows in a
// decompiled pixel shader, p computed from a position the shader rebuilt from depth (which the
// rebuild's text fix makes the true point), and clip x the coordinate the shader reads that same
// depth texture at again (SSAO's samples, a screen-space reflection's march, contact shadows),
// into a Reprojection: the text fix that moves clip x to where this eye's image has the point.
//
// Why: the rebuild's fix makes p the point the pixel shows in this eye; VP is the mono matrix, so
// clip is where the mono image has it, while the depth texture read there is this eye's. This eye's
// projection is the mono one followed by x += s.x * (w - s.y) in clip space (docs/stereo-math.md),
// so clip.x + s.x * (clip.w - s.y) is exact, in NDC units; a VP to another space (UV: u = 0.5 x +
// 0.5 w) scales x by a = VP's row of x times InvM's column of NDC x, which the fix computes. Before
// this, correcting the rebuild alone made such a shader worse than leaving it: its samples landed
// at mono positions in this eye's image.
//
// Only where the depth texture is read at it: a shadow map or a projector's texture read at a
// light-space transform of the same point was drawn once for both eyes and stays mono. What a
// re-projection that reads only another texture (a temporal history, a colour buffer) should be
// is not told apart here: left as it is.
#include "passes/deferred_unprojection/register_analyses.h"
#include "passes/ir/image_instructions.h"

#include <set>

namespace stereoshift::deferred {

namespace {

// The operands of `def` that are ids of values (not the literal lanes of an extract, insert or
// shuffle, nor an extended instruction's number).
std::vector<uint32_t> valueOperands(const Instruction& def) {
  size_t from = 0, to = def.operands.size();
  switch (def.opcode) {
    case spv::OpCompositeExtract: to = std::min<size_t>(to, 1); break;
    case spv::OpCompositeInsert: to = std::min<size_t>(to, 2); break;
    case spv::OpVectorShuffle: to = std::min<size_t>(to, 2); break;
    case spv::OpExtInst: from = 2; break;
    default: break;
  }
  return {def.operands.begin() + std::min(from, to), def.operands.begin() + to};
}

// Whether `from` is computed from one of `targets`: through every instruction (a loop's phi too),
// looking at each value once.
bool computedFrom(const Decomposer& d, uint32_t from, const std::set<uint32_t>& targets, size_t& visits) {
  std::set<uint32_t> seen;
  std::vector<uint32_t> stack{from};
  while (!stack.empty()) {
    const uint32_t id = stack.back();
    stack.pop_back();
    if (targets.count(id)) return true;
    if (!seen.insert(id).second) continue;
    ++visits;
    if (const Instruction* def = d.definition(id))
      for (uint32_t operand : valueOperands(*def))
        if (d.definition(operand)) stack.push_back(operand);
  }
  return false;
}

// A texel read: the texture it reads and the coordinate it reads it at.
struct TexelRead {
  std::string texture;
  uint32_t coordinate = 0;
};

std::vector<TexelRead> texelReads(RegisterAnalyses& a) {
  std::vector<TexelRead> reads;
  spirv::forEachFunctionInstruction(a.registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (!spirv::isTexelRead(inst.opcode) || inst.operands.size() < 2) return;
    for (const std::string& texture : sourcesOf(a.flow, a.d, {inst.resultId, 0}).textures)
      reads.push_back({texture, inst.operand(1)});
  });
  return reads;
}

// The rebuilds a re-projection may follow: fixed ones whose correction's column is InvM's column of
// NDC x as the text names it, read from a depth texture.
bool followable(const RowProduct& p) {
  return p.reason.empty() && !p.interpolated && !p.fix.scaleFromTheMatrix && !p.fix.basisRay && p.z.texel &&
         p.qIds[0] && p.qIds[1] && p.qIds[2];
}

}  // namespace

std::vector<Reprojection> findReprojections(RegisterAnalyses& a, const std::vector<RowProduct>& rebuilds) {
  std::vector<Reprojection> found;
  if (a.otherProducts.empty() || std::none_of(rebuilds.begin(), rebuilds.end(), followable)) return found;
  const std::vector<TexelRead> reads = texelReads(a);
  for (const auto& clip : a.otherProducts) {
    if (!clip[0] || !clip[3]) continue;  // clip x and w
    const Member& x = *clip[0];
    // p's axes by the lanes of its terms (`r4.xyzw = r2.xxxx * cb0[7].xyzw + ...`: lanes 0-2 of p).
    std::array<std::optional<Lane>, 3> axis;
    for (const auto& [term, c] : x.byTerm)
      if (term.lane < 3 && !axis[term.lane]) axis[term.lane] = term;
    for (const RowProduct& p : rebuilds) {
      if (!followable(p)) continue;
      std::set<uint32_t> q;
      for (uint32_t id : p.qIds)
        if (id) q.insert(id);
      bool fromQ = true;
      for (const auto& [term, c] : x.byTerm) fromQ = fromQ && computedFrom(a.d, term.id, q, a.factorVisits);
      if (!fromQ) continue;
      const std::set<uint32_t> clipXw{x.at.id, clip[3]->at.id};
      const auto again = std::find_if(reads.begin(), reads.end(), [&](const TexelRead& r) {
        return p.z.textures.count(r.texture) && computedFrom(a.d, r.coordinate, clipXw, a.factorVisits);
      });
      if (again == reads.end()) continue;
      Reprojection r;
      r.texture = again->texture;
      std::array<const Member*, 4> rows = clip;
      r.rows = rowsText(a.registers, rows);
      r.fix.lines = {a.lines.lineOf(x.at.id), a.lines.lineOf(clip[3]->at.id)};
      r.fix.lanes = {x.at.lane, clip[3]->at.lane};
      r.fix.afterLine = std::max(r.fix.lines[0], r.fix.lines[1]);
      for (uint32_t k = 0; k < 3; ++k) {
        r.fix.column[k] = p.fix.column[k];
        if (axis[k]) r.fix.rowX[k] = elementText(a.registers, x.byTerm.at(*axis[k]));
      }
      if (!axis[0] || !axis[1] || !axis[2])
        r.reason = "the re-projected point's x, y and z are not lanes 0-2 of the values it is computed in";
      else if (std::any_of(r.fix.rowX.begin(), r.fix.rowX.end(), [](const std::string& e) { return e.empty(); }))
        r.reason = "a matrix element is not a cbuffer element the source can name";
      else if (!r.fix.lines[0] || !r.fix.lines[1])
        r.reason = "clip x or w is computed outside the main file (an #include or a macro)";
      found.push_back(std::move(r));
      break;
    }
  }
  return found;
}

}  // namespace stereoshift::deferred
