// deferred-unprojection's re-projections: turns `clip = VP * (p, 1)` over cbuffer rows in a
// decompiled pixel shader, p computed from a position the shader rebuilt from depth (which the
// rebuild's text fix makes the true point: a matrix rebuild's q, or the view-space x a per-component
// view ray corrects), and clip x the coordinate the shader reads that same depth texture at again
// (SSAO's samples, a screen-space reflection's march, contact shadows), into a Reprojection: the
// text fix that moves clip x to where this eye's image has the point.
//
// Why: the rebuild's fix makes p the point the pixel shows in this eye; VP is the mono matrix, so
// clip is where the mono image has it, while the depth texture read there is this eye's. This eye's
// projection is the mono one followed by x += s.x * (w - s.y) in clip space (docs/stereo-math.md),
// so clip.x + s.x * (clip.w - s.y) is exact, in NDC units; a VP to another space (UV: u = 0.5 x +
// 0.5 w) scales x by a = VP's row of x times InvM's column of NDC x, which the fix computes (after a
// view ray, whose x moves by |k| = 1/P00 per unit of NDC x times the depth, VP's element of x times
// |k|). Before this, correcting the rebuild alone made such a shader worse than leaving it: its
// samples landed at mono positions in this eye's image.
//
// Only where the depth texture is read at it: a shadow map or a projector's texture read at a
// light-space transform of the same point was drawn once for both eyes and stays mono. What a
// re-projection that reads only another texture (a temporal history, a colour buffer) should be
// is not told apart here: left as it is.
#include "passes/deferred_unprojection/register_analyses.h"
#include "passes/ir/image_instructions.h"

#include <array>
#include <optional>
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

// The values computed from `seeds` (through every instruction, a loop's phi too), seeds included:
// one pass over the module in order per loop nesting it takes to settle, so each question below is a
// lookup, whatever the number of products and reads.
class Dependents {
 public:
  explicit Dependents(const spirv::Module& m) {
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (inst.resultId) order_.push_back(&inst);
    });
  }
  size_t size() const { return order_.size(); }
  std::set<uint32_t> of(std::set<uint32_t> reached, size_t& work) const {
    for (bool changed = true; changed;) {
      changed = false;
      for (const Instruction* inst : order_) {
        ++work;
        if (reached.count(inst->resultId)) continue;
        const std::vector<uint32_t> operands = valueOperands(*inst);
        if (std::any_of(operands.begin(), operands.end(), [&](uint32_t id) { return reached.count(id) > 0; }))
          changed = reached.insert(inst->resultId).second || changed;
      }
    }
    return reached;
  }

 private:
  std::vector<const Instruction*> order_;
};

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

// A corrected position a re-projection may follow: the values it is traced back to, the depth
// texture it was rebuilt from, and how the correction moves it along the screen's x (the column of
// NDC x: InvM's for a rebuild, (|k|, 0, 0) in view space for a view ray, k = 1/P00).
struct Followed {
  std::set<uint32_t> values;  // with Dependents::of, every value computed from them
  std::set<std::string> textures;
  std::array<std::string, 3> column;
  bool viewRay = false;  // only its x is corrected: p's x is the term computed from it
};

std::vector<Followed> followedPositions(const std::vector<RowProduct>& rebuilds, const std::vector<ComponentRay>& rays) {
  std::vector<Followed> out;
  // Fixed rebuilds whose correction's column is InvM's column of NDC x as the text names it (not
  // scaled at run time), read from a depth texture.
  for (const RowProduct& p : rebuilds) {
    if (!p.reason.empty() || p.interpolated || p.fix.scaleFromTheMatrix || p.fix.basisRay || !p.z.texel ||
        !p.qIds[0] || !p.qIds[1] || !p.qIds[2])
      continue;
    Followed f{{}, p.z.textures, {p.fix.column[0], p.fix.column[1], p.fix.column[2]}, false};
    for (uint32_t id : p.qIds)
      if (id) f.values.insert(id);
    out.push_back(std::move(f));
  }
  for (const ComponentRay& r : rays)
    if (r.reason.empty() && r.xId) out.push_back({{r.xId}, r.depth.textures, {"abs(" + r.fix.scale + ")", "0", "0"}, true});
  return out;
}

// VP's coefficients of p's x, y and z in clip x: by the lanes of p's terms (`r4.xyzw = r2.xxxx *
// cb0[7].xyzw + ...`: lanes 0-2 of p), or, after a view ray, the coefficient of the one term computed
// from its x (the column has nothing in y and z). Empty where the text does not tell them.
std::optional<std::array<std::string, 3>> rowOfX(RegisterAnalyses& a, const Member& x, const Followed& f) {
  std::array<std::string, 3> row;
  if (f.viewRay) {
    row = {"", "0", "0"};
    for (const auto& [term, c] : x.byTerm)
      if (f.values.count(term.id)) {
        if (!row[0].empty()) return std::nullopt;
        row[0] = elementText(a.registers, c);
      }
    return row;
  }
  for (const auto& [term, c] : x.byTerm) {
    if (term.lane > 2 || !row[term.lane].empty()) return std::nullopt;
    row[term.lane] = elementText(a.registers, c);
  }
  return row;
}

}  // namespace

std::vector<Reprojection> findReprojections(RegisterAnalyses& a, const std::vector<RowProduct>& rebuilds,
                                            const std::vector<ComponentRay>& rays) {
  std::vector<Reprojection> found;
  if (a.otherProducts.empty()) return found;
  std::vector<Followed> followed = followedPositions(rebuilds, rays);
  if (followed.empty()) return found;
  const Dependents dependents(a.registers);
  const size_t start = a.factorVisits;
  constexpr size_t kPassesPerShader = 256;
  for (Followed& f : followed) f.values = dependents.of(std::move(f.values), a.factorVisits);
  const std::vector<TexelRead> reads = texelReads(a);
  for (const auto& clip : a.otherProducts) {
    if (!clip[0] || !clip[3]) continue;  // clip x and w
    const Member& x = *clip[0];
    std::optional<std::set<uint32_t>> fromClip;  // what clip x and w reach, once per product
    for (const Followed& f : followed) {
      // Every term of p is computed from the rebuilt position; after a view ray, one of them.
      size_t fromIt = 0;
      for (const auto& [term, c] : x.byTerm) fromIt += f.values.count(term.id);
      if (fromIt == 0 || (!f.viewRay && fromIt != x.byTerm.size())) continue;
      // One pass per product: a shader of a great many products (a fuzzer's) stops at a budget
      // linear in its size rather than walking it once for each.
      if (!fromClip && a.factorVisits - start > kPassesPerShader * dependents.size()) return found;
      if (!fromClip) fromClip = dependents.of({x.at.id, clip[3]->at.id}, a.factorVisits);
      const auto again = std::find_if(reads.begin(), reads.end(), [&](const TexelRead& r) {
        return f.textures.count(r.texture) && fromClip->count(r.coordinate);
      });
      if (again == reads.end()) continue;
      Reprojection r;
      r.texture = again->texture;
      r.rows = rowsText(a.registers, clip);
      r.fix.lines = {a.lines.lineOf(x.at.id), a.lines.lineOf(clip[3]->at.id)};
      r.fix.lanes = {x.at.lane, clip[3]->at.lane};
      r.fix.afterLine = std::max(r.fix.lines[0], r.fix.lines[1]);
      r.fix.column = f.column;
      const auto row = rowOfX(a, x, f);
      if (row) r.fix.rowX = *row;
      if (!row)
        r.reason = "the re-projected point's x, y and z are not told apart by the lanes of the values it is computed in";
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
