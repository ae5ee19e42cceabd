// See row_products.h: unprojections through cbuffer rows, as decompiled HLSL writes them.
#include "passes/deferred_unprojection/row_products.h"

#include "passes/deferred_unprojection/linear_form.h"
#include "passes/deferred_unprojection/register_analyses.h"

#include <bit>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace stereoshift::deferred {

using namespace linear;

namespace {

std::optional<Member> memberOf(Decomposer& d, Lane at) {
  Member member{at, {}, {}, 0, ""};
  bool hasTranslation = false;
  std::vector<const Coefficient*> elements;
  for (const Part& part : d.form(at)) {
    if (!part.coefficient.uniform() || part.coefficient.path.size() < 2) return std::nullopt;
    if (!part.term) {
      if (hasTranslation) return std::nullopt;
      hasTranslation = true;
      member.translation = part.coefficient;
    } else if (!member.byTerm.emplace(*part.term, part.coefficient).second) {
      return std::nullopt;
    }
  }
  if (!hasTranslation || member.byTerm.size() != 3) return std::nullopt;  // w = 1: a point
  elements.push_back(&member.translation);
  for (const auto& [term, c] : member.byTerm) elements.push_back(&c);
  auto same = [&](auto&& key) {
    return std::all_of(elements.begin(), elements.end(), [&](const Coefficient* c) { return key(*c) == key(*elements[0]); });
  };
  auto lane = [](const Coefficient& c) { return c.path.back(); };
  auto vector = [](const Coefficient& c) { return pathKey(c.root, c.path, c.path.size() - 1); };
  if (same(lane) && !same(vector)) {  // column storage
    member.index = lane(*elements[0]);
    std::set<std::string> columns;
    for (const Coefficient* c : elements) columns.insert(vector(*c));
    if (columns.size() != 4) return std::nullopt;
    for (const auto& column : columns) member.matrix += "c:" + column + ";";
  } else if (same(vector) && !same(lane)) {  // row storage: the row's array index
    const AccessPath& path = elements[0]->path;
    member.index = path[path.size() - 2];
    member.matrix = "r:" + pathKey(elements[0]->root, path, path.size() - 2);
  } else {
    return std::nullopt;
  }
  return member;
}

// The candidates, grouped into matrices and ordered into q's four components: column storage by
// lane, row storage by four consecutive rows. Each component once per product; a matrix met again
// with a component already taken starts another product of it.
std::vector<std::array<const Member*, 4>> groupProducts(const std::vector<Member>& members) {
  std::vector<std::array<const Member*, 4>> products;
  std::map<std::string, std::vector<std::map<uint32_t, const Member*>>> open;
  for (const Member& m : members) {
    std::string key = m.matrix;
    for (const auto& [term, c] : m.byTerm) key += "|" + std::to_string(term.id) + "." + std::to_string(term.lane);
    auto& groups = open[key];
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return !g.count(m.index); });
    if (it == groups.end()) it = groups.emplace(groups.end());
    (*it)[m.index] = &m;
  }
  for (const auto& [key, groups] : open)
    for (const auto& g : groups) {
      // Column storage names each component by its lane, so a product the compiler narrowed to
      // the lanes the shader uses (`r1.xyw = ...`) is still one, with its w; rows need all four
      // to say which is w. A point whose w the shader never reads (Unreal's `mul(float4(ndc *
      // depth, depth, 1), ScreenToWorld).xyz`, an affine map) is x, y and z alone: lanes 0-2 of
      // the columns, or three consecutive rows; only the screen-to-world form, whose correction
      // needs no w, takes it (findRowProducts).
      bool columns = key.starts_with("c:");
      std::array<const Member*, 4> q{};
      if (columns) {
        const bool point = g.count(0) && g.count(1) && g.count(2);
        if ((!g.count(3) && !point) || g.size() < 2) continue;
        for (const auto& [index, member] : g) q[index] = member;
      } else {
        uint32_t first = g.begin()->first;
        if (g.size() < 3 || g.rbegin()->first != first + g.size() - 1) continue;  // rows k..k+3 (or k..k+2)
        for (const auto& [index, member] : g) q[index - first] = member;
      }
      products.push_back(q);
    }
  return products;
}

}  // namespace

std::string rowsText(const spirv::Module& m, const std::array<const Member*, 4>& q) {
  // In numeric order (cb3[8] before cb3[10]): keyed by the root and the path.
  std::map<std::vector<uint32_t>, std::string> vectors;
  auto add = [&](Coefficient c) {
    c.path.pop_back();  // the element's vector
    c.scale = 1.0f;
    std::vector<uint32_t> key{c.root};
    key.insert(key.end(), c.path.begin(), c.path.end());
    vectors.emplace(std::move(key), elementText(m, c));
  };
  for (const Member* member : q) {
    if (!member) continue;
    add(member->translation);
    for (const auto& [term, c] : member->byTerm) add(c);
  }
  std::string text;
  for (const auto& [key, vector] : vectors) text += (text.empty() ? "" : ", ") + vector;
  return text;
}

bool hasCbufferRows(const spirv::Module& m) {
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassUniform) continue;
    const Instruction* block = m.definition(m.pointeeType(inst.typeId));
    if (!block || block->opcode != spv::OpTypeStruct) continue;
    for (uint32_t member : block->operands) {
      // A float4 array (cb1[30]) or a matrix of float4 rows (a named float4x4, when the dump kept
      // the game's reflection: `InvViewProj._m00_m10_m20_m30`).
      const Instruction* rows = m.definition(member);
      if (rows && (rows->opcode == spv::OpTypeArray || rows->opcode == spv::OpTypeMatrix) && isFloat4(m, rows->operand(0)))
        return true;
    }
  }
  return false;
}

namespace {


struct Factors;
void collectFactors(Decomposer& d, SourceAnalysis& flow, Lane at, bool divides, Factors& out, int depth);
bool scaledScreenTerm(Decomposer& d, SourceAnalysis& flow, Lane term, Lane depth, uint32_t lane, size_t& visits);
// The one screen input lane a product reads as it is (plainScreenFactor).
struct PlainScreen {
  Lane lane;
  bool fragCoord = false;
};
std::optional<PlainScreen> plainScreenFactor(Decomposer& d, SourceAnalysis& flow, Lane term, std::optional<Lane> besides,
                                             size_t& visits);

// The camera c of a view vector `sign` * (c - p) that one lane of `f` (its linear form) is, where p
// is the affine q's component `component` itself (its parts all in f times -sign, c the one part
// left over, times sign).
std::optional<Coefficient> cameraBesidesPoint(const Linear& f, const Linear& component, float sign) {
  if (f.size() != component.size() + 1) return std::nullopt;
  std::vector<bool> used(f.size(), false);
  for (const Part& part : component) {
    bool matched = false;
    for (size_t k = 0; k < f.size() && !matched; ++k) {
      const Coefficient& c = f[k].coefficient;
      if (used[k] || f[k].term != part.term || c.root != part.coefficient.root || c.path != part.coefficient.path ||
          c.scale != -sign * part.coefficient.scale)
        continue;
      used[k] = matched = true;
    }
    if (!matched) return std::nullopt;
  }
  for (size_t k = 0; k < f.size(); ++k) {
    const Coefficient& c = f[k].coefficient;
    if (!used[k]) return !f[k].term && c.uniform() && c.scale == sign && c.path.size() >= 2 ? std::optional(c) : std::nullopt;
  }
  return std::nullopt;
}

// The view vectors c - p (c a cbuffer vector), x, y and z computed by one statement: p = q.xyz / q.w
// (or times its reciprocal), or q.xyz itself where q has no w (the screen-to-world form of a
// point). The camera the matrix shows, which c is compared with in the text: InvM's projection
// centre, its column of z over that column's w; or where the screen-to-world map sends depth 0,
// its translation column.
// `position`: the rebuild's fix, whose screen scale (scaleFromTheMatrix) each camera fix takes too.
std::vector<CameraTextFix> findCameraVectors(RegisterAnalyses& a, const std::array<const Member*, 4>& q, Lane x, Lane z,
                                             bool scaled, const RowProductTextFix& position) {
  const spirv::Module& registers = a.registers;
  Decomposer& d = a.d;
  struct Hit {
    uint32_t lane = 0, component = 0;
    Coefficient camera;
    bool fromCamera = false;
  };
  std::map<uint32_t, std::vector<Hit>> byValue;
  std::set<Lane> seen;
  spirv::forEachFunctionInstruction(registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFAdd && inst.opcode != spv::OpFSub) return;
    const uint32_t count = d.lanes(inst.resultId);
    for (uint32_t lane = 0; lane < count; ++lane) {
      Lane at = d.canonical({inst.resultId, lane});
      if (at.id != inst.resultId || !seen.insert(at).second) continue;
      const Linear& f = d.form(at);
      if (!q[3]) {
        for (uint32_t i = 0; i < 3; ++i)
          for (float sign : {1.0f, -1.0f})
            if (auto camera = cameraBesidesPoint(f, d.form(q[i]->at), sign))
              byValue[inst.resultId].push_back({lane, i, *camera, sign < 0});
        continue;
      }
      if (f.size() != 2) continue;
      // c - p, or p - c (the direction from the camera, as a reflection or a fog ray reads it).
      const Part* camera = nullptr;
      const Part* position = nullptr;
      for (const Part& part : f) {
        if (!part.term && part.coefficient.uniform() && std::abs(part.coefficient.scale) == 1.0f && part.coefficient.path.size() >= 2) camera = &part;
        else if (part.term && !part.coefficient.uniform() && std::abs(part.coefficient.scale) == 1.0f) position = &part;
      }
      if (!camera || !position || camera->coefficient.scale != -position->coefficient.scale) continue;
      const bool fromCamera = camera->coefficient.scale < 0;
      Coefficient c = camera->coefficient;
      c.scale = 1.0f;
      const Instruction* divide = d.definition(position->term->id);
      auto laneOf = [&](uint32_t id, Lane at) { return d.canonical({id, d.isVector(id) ? at.lane : 0}); };
      std::optional<Lane> numerator;
      if (divide && divide->opcode == spv::OpFDiv && laneOf(divide->operand(1), *position->term) == q[3]->at)
        numerator = laneOf(divide->operand(0), *position->term);
      // Or times the reciprocal (fxc's rcp; the decompiler's `r.w = 1 / r.w; p = r.xyz * r.www;`).
      for (int side = 0; divide && divide->opcode == spv::OpFMul && side < 2; ++side) {
        const Lane other = laneOf(divide->operand(1 - side), *position->term);
        const Instruction* r = d.definition(other.id);
        if (r && r->opcode == spv::OpFDiv && analysis::constantValue(registers, r->operand(0)) == 0x3f800000u &&
            laneOf(r->operand(1), other) == q[3]->at)
          numerator = laneOf(divide->operand(side), *position->term);
      }
      if (!numerator) continue;
      for (uint32_t i = 0; i < 3; ++i)
        if (*numerator == q[i]->at) byValue[inst.resultId].push_back({lane, i, c, fromCamera});
    }
  });
  std::vector<CameraTextFix> found;
  for (const auto& [id, hits] : byValue) {
    CameraTextFix fix;
    std::array<bool, 3> have{};
    std::set<bool> directions;
    for (const Hit& h : hits) {
      if (have[h.component]) continue;
      have[h.component] = true;
      fix.lanes[h.component] = h.lane;
      Coefficient c = h.camera;
      c.scale = 1.0f;
      fix.camera[h.component] = elementText(registers, c);
      directions.insert(h.fromCamera);
    }
    if (!have[0] || !have[1] || !have[2] || directions.size() != 1) continue;
    fix.fromCamera = *directions.begin();
    fix.line = a.lines.lineOf(id);
    bool named = fix.line != 0;
    for (uint32_t i = 0; i < 4; ++i) {
      if (i < 3) fix.columnX[i] = elementText(registers, q[i]->byTerm.at(x));
      if (!q[i]) fix.centre[i] = "1";  // an affine map's w
      else fix.centre[i] = elementText(registers, scaled ? q[i]->translation : q[i]->byTerm.at(z));
      named &= (i == 3 || (!fix.columnX[i].empty() && !fix.camera[i].empty())) && !fix.centre[i].empty();
    }
    fix.scaleFromTheMatrix = position.scaleFromTheMatrix;  // moved by the scaled column: the half-width's columns
    fix.affine = scaled;
    fix.columnZ = position.columnZ;
    fix.translation = position.translation;
    if (named) found.push_back(std::move(fix));
  }
  return found;
}

// The fragment's own depth, SV_Position.z read as it is: a forward pass (Unreal's materials:
// `mul(float4(SvPosition.xyz, 1), View.SVPositionToTranslatedWorld)`) rebuilds the point it shades
// from it, with the pixel position beside it, as a deferred pass does from the depth buffer.
bool fragmentDepth(const Sources& s) {
  return s.fragmentDepth && !s.fragCoord && !s.varying && !s.texel && !s.uniform && !s.arithmetic;
}

// Whether the three terms are lanes x, y and z of one interpolated input, no texel in them.
bool interpolatedPosition(SourceAnalysis& flow, Decomposer& d, const std::map<Lane, Coefficient>& terms) {
  uint32_t lanes = 0;
  std::set<std::string> inputs;
  for (const auto& [term, c] : terms) {
    Sources s = sourcesOf(flow, d, term);
    if (!s.varying || s.fragCoord || s.texel || s.other || std::popcount(s.inputLanes) != 1 || (lanes & s.inputLanes))
      return false;
    lanes |= s.inputLanes;
    inputs.insert(s.inputs.begin(), s.inputs.end());
  }
  return lanes == 7u && inputs.size() == 1;
}





// The screen-to-world form's term `term` = (the pixel's coordinate) * z: the coordinate, the operand of
// the product that is not z.
std::optional<Lane> screenPartOf(Decomposer& d, Lane term, Lane z) {
  const Lane at = d.canonical(term);
  const Instruction* def = d.definition(at.id);
  if (!def || def->opcode != spv::OpFMul || def->operands.size() != 2) {
    if (!def || def->opcode != spv::OpVectorTimesScalar || def->operands.size() != 2) return std::nullopt;
    if (d.canonical({def->operand(1), 0}) != d.canonical(z)) return std::nullopt;
    return Lane{def->operand(0), at.lane};
  }
  auto lane = [&](uint32_t id) { return Lane{id, d.isVector(id) ? at.lane : 0}; };
  if (d.canonical(lane(def->operand(0))) == d.canonical(z)) return lane(def->operand(1));
  if (d.canonical(lane(def->operand(1))) == d.canonical(z)) return lane(def->operand(0));
  return std::nullopt;
}

// The columns the run-time half-width of the screen coordinate reads (RowProductTextFix::
// scaleFromTheMatrix), as the source names them: the depth's and the constant one (the
// screen-to-world form's reads the depth's alone).
void nameTheScalesColumns(const spirv::Module& registers, const std::array<const Member*, 4>& q, Lane z, RowProduct& p) {
  p.fix.scaleFromTheMatrix = true;
  for (uint32_t i = 0; i < 4; ++i) {
    if (!q[i]) continue;  // the w of an affine map's point (the screen-to-world form's scale reads x, y, z)
    p.fix.columnZ[i] = elementText(registers, q[i]->byTerm.at(z));
    p.fix.translation[i] = elementText(registers, q[i]->translation);
    if (p.fix.columnZ[i].empty() || p.fix.translation[i].empty())
      p.reason = "a matrix element is not a cbuffer element the source can name";
  }
}

std::vector<RowProduct> findRowProducts(RegisterAnalyses& a) {
  const spirv::Module& registers = a.registers;
  SourceAnalysis& flow = a.flow;
  Decomposer& d = a.d;
  const LineMap& lines = a.lines;
  // Every lane of every float value that is one component of a product, once (by the value that
  // computes it), in module order, kept for findReprojections.
  std::vector<Member>& members = a.members;
  std::set<Lane> seen;
  spirv::forEachFunctionInstruction(registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (!inst.resultId || !inst.typeId) return;
    const Instruction* type = registers.definition(inst.typeId);
    bool scalar = type && type->opcode == spv::OpTypeFloat && type->operand(0) == 32;
    if (!scalar && !isFloat4(registers, inst.typeId)) return;
    for (uint32_t lane = 0; lane < (scalar ? 1u : 4u); ++lane) {
      Lane at = d.canonical({inst.resultId, lane});
      if (!seen.insert(at).second) continue;
      if (auto member = memberOf(d, at)) members.push_back(std::move(*member));
    }
  });
  auto screen = [](const Sources& s, uint32_t lane) {
    return (s.fragCoord || s.varying) && !s.texel && !s.other && (s.inputLanes & 3u) == lane;
  };
  std::vector<RowProduct> found;
  for (const auto& q : groupProducts(members)) {
    RowProduct p;
    // Which term is which: the pixel's x (lane 0 of the input), its y (lane 1), the depth.
    // Or the screen-to-world form: the pixel's x and y each scaled by the depth (q = M * (ndc.x*z,
    // ndc.y*z, z, 1)), both terms made from the screen and a texel.
    std::optional<Lane> x, y, z;
    bool other = false;
    std::optional<bool> scaled;
    auto scaledScreen = [](const Sources& s, uint32_t lane) {
      return (s.fragCoord || s.varying) && s.texel && !s.other && (s.inputLanes & 3u) == lane;
    };
    const Member* any = q[3] ? q[3] : q[0];  // every component has the same three terms
    for (const auto& [term, c] : any->byTerm) {
      Sources s = sourcesOf(flow, d, term);
      const bool plainX = screen(s, 1u), plainY = screen(s, 2u), scaledX = scaledScreen(s, 1u), scaledY = scaledScreen(s, 2u);
      if ((plainX || scaledX) && !x && (!scaled || *scaled == scaledX)) x = term, p.x = s, scaled = scaledX;
      else if ((plainY || scaledY) && !y && (!scaled || *scaled == scaledY)) y = term, p.y = s, scaled = scaledY;
      else if ((texelOnly(s) || fragmentDepth(s)) && !z) z = term, p.z = s;
      else other = true;
    }
    if (other || !x || !y || !z) {
      if (interpolatedPosition(flow, d, any->byTerm)) {
        RowProduct seen;
        seen.interpolated = true;
        seen.rows = rowsText(registers, q);
        for (const auto& [term, c] : any->byTerm) seen.x |= sourcesOf(flow, d, term);
        for (uint32_t i = 0; i < 4; ++i)
          if (q[i]) seen.fix.afterLine = std::max(seen.fix.afterLine, lines.lineOf(q[i]->at.id));
        found.push_back(std::move(seen));
      } else {
        a.otherProducts.push_back(q);
      }
      continue;
    }
    if (!q[3] && !*scaled) continue;  // (ndc, depth, 1) needs q.w for its divide: not a rebuild
    // Scaled terms must be the coordinate times that very depth; else q is a point (findReprojections).
    if (*scaled && (!scaledScreenTerm(d, flow, *x, *z, 1u, a.factorVisits) ||
                    !scaledScreenTerm(d, flow, *y, *z, 2u, a.factorVisits))) {
      a.otherProducts.push_back(q);
      continue;
    }
    // A pixel's x that is a screen input as it is, or scaled by one constant or uniform (a UV, a pixel
    // position), is not known to run from -1 to 1 across the screen: a matrix from UV space has
    // twice InvM's column where the correction needs InvM's own. Reported, not fixed.
    // Unless the depth is sampled at those very coordinates: then they are the depth buffer's UV, over
    // [0, 1] where NDC is over [-1, 1], and the correction takes half the matrix's column of u. The
    // screen-to-world form's terms are the coordinate times the depth: the same, on the coordinate.
    bool uv = false, notNdc = false;
    if (!*scaled) {
      notNdc = notKnownNdc(d, flow, *x);
      uv = notNdc && depthSampledAt(d, *z, *x, *y);
    } else if (auto plain = plainScreenFactor(d, flow, *x, *z, a.factorVisits)) {
      // A texture coordinate read as it is may carry NDC (a full-screen pass that hands its corners
      // on): taken as such unless the depth is sampled at it. A pixel position never is.
      auto screenX = screenPartOf(d, *x, *z), screenY = screenPartOf(d, *y, *z);
      uv = screenX && screenY && depthSampledAt(d, *z, *screenX, *screenY);
      notNdc = uv || plain->fragCoord;
    }
    // A coordinate of unknown scale into a matrix with a w: the matrix shows the scale (its optical
    // axis), computed where the correction runs. The screen-to-world form's is not derived here.
    const bool scaleFromTheMatrix = notNdc && !uv && q[0] && q[1] && q[2] && (q[3] || *scaled);
    if (notNdc && !uv && !scaleFromTheMatrix)
      p.reason = "the pixel's x is a texture coordinate or pixel position as it is, not NDC (no -1 offset): the "
                 "matrix may map UV space, whose column is not the correction's; left for a person";
    if (scaleFromTheMatrix) nameTheScalesColumns(registers, q, *z, p);
    if (*scaled) {
      for (const Lane& term : {*x, *y}) p.scaledTerms.insert({lines.lineOf(d.canonical(term).id), d.canonical(term).lane});
      p.fix.scaledByDepth = true;
      p.fix.depthLine = lines.lineOf(z->id);
      p.fix.depthLane = z->lane;
      if (!p.fix.depthLine && p.reason.empty()) p.reason = "the depth is computed outside the main file (an #include or a macro)";
    }
    auto halvedForUv = [uv](std::string element) { return uv && !element.empty() ? "(0.5 * " + element + ")" : element; };
    if (q[0] && q[1] && q[2] && (q[3] || *scaled)) p.cameras = findCameraVectors(a, q, *x, *z, *scaled, p.fix);
    for (CameraTextFix& camera : p.cameras)
      for (std::string& element : camera.columnX) element = halvedForUv(element);
    p.fix.uvOfTheDepthTexture = uv;
    p.depthId = d.canonical(*z).id;
    p.rows = rowsText(registers, q);
    for (uint32_t i = 0; i < 4; ++i) {
      p.fix.present[i] = q[i] != nullptr;
      if (!q[i]) continue;  // a lane the shader does not compute
      p.qIds[i] = q[i]->at.id;
      p.fix.column[i] = halvedForUv(elementText(registers, q[i]->byTerm.at(*x)));
      p.fix.lines[i] = lines.lineOf(q[i]->at.id);
      p.fix.lanes[i] = q[i]->at.lane;
      p.fix.afterLine = std::max(p.fix.afterLine, p.fix.lines[i]);
      if (p.fix.column[i].empty()) p.reason = "a matrix element is not a cbuffer element the source can name";
      else if (!p.fix.lines[i] && p.reason.empty())
        p.reason = lines.present() ? "a component is computed outside the main file (an #include or a macro)"
                                   : "the module has no source lines";
    }
    found.push_back(std::move(p));
  }
  return found;
}

// A product's factors, through multiplications, divisions, negations and moves: each a lane and
// whether it divides. `through`: the products and quotients looked through.
struct Factors {
  std::vector<std::pair<Lane, bool>> factors;
  std::set<uint32_t> through;
  // Lanes looked at: a view ray has a handful of factors, and a tree of shared products
  // (`a1 = a0 * a0` chained) must not be walked once per path.
  int visits = 0;
  bool tooLarge = false;
};
constexpr int kMaxFactorVisits = 32;

// A value computed from texels, uniforms and constants only (a depth made linear, `1 / (a*t + b)`,
// texelOnly) is one factor, not looked into.
void collectFactors(Decomposer& d, SourceAnalysis& flow, Lane at, bool divides, Factors& out, int depth) {
  if (++out.visits > kMaxFactorVisits || out.tooLarge) {
    out.tooLarge = true;
    return;
  }
  at = d.canonical(at);
  const Instruction* def = d.definition(at.id);
  auto lane = [&](uint32_t id) { return Lane{id, d.isVector(id) ? at.lane : 0}; };
  bool whole = texelOnly(sourcesOf(flow, d, at));
  if (def && depth < 16 && !whole) {
    switch (def->opcode) {
      case spv::OpFMul: case spv::OpFDiv:
        out.through.insert(def->resultId);
        collectFactors(d, flow, lane(def->operand(0)), divides, out, depth + 1);
        collectFactors(d, flow, lane(def->operand(1)), def->opcode == spv::OpFDiv ? !divides : divides, out, depth + 1);
        return;
      case spv::OpVectorTimesScalar:
        out.through.insert(def->resultId);
        collectFactors(d, flow, {def->operand(0), at.lane}, divides, out, depth + 1);
        collectFactors(d, flow, {def->operand(1), 0}, divides, out, depth + 1);
        return;
      case spv::OpFNegate:
        out.through.insert(def->resultId);
        collectFactors(d, flow, lane(def->operand(0)), divides, out, depth + 1);
        return;
      default: break;
    }
  }
  out.factors.push_back({at, divides});
}

// Whether `term` is the pixel's coordinate (input lane bit `lane`) times `depth` and constants: its
// factors are that depth once and otherwise made from the screen alone (`v0.x / v0.w` is two).
bool scaledScreenTerm(Decomposer& d, SourceAnalysis& flow, Lane term, Lane depth, uint32_t lane, size_t& visits) {
  Factors f;
  collectFactors(d, flow, term, false, f, 0);
  visits += static_cast<size_t>(f.visits);
  if (f.tooLarge) return false;
  int depths = 0;
  uint32_t lanes = 0;
  const Lane z = d.canonical(depth);
  for (const auto& [factor, divides] : f.factors) {
    if (d.constant(factor)) continue;
    // A screen size with the coordinate (a UV: `v0.xy * cb0[4].zw`): told from NDC by the caller.
    if (d.uniformElement(factor)) continue;
    Sources s = sourcesOf(flow, d, factor);
    if (!divides && factor == z) ++depths;
    else if ((s.fragCoord || s.varying) && !s.texel && !s.other) lanes |= s.inputLanes;
    else return false;
  }
  return depths == 1 && (lanes & 3u) == lane;
}

// The one screen input lane, read as it is, among a product's factors besides `besides` (its depth),
// constants and uniforms: a pixel position (gl_FragCoord / SV_Position) or a texture coordinate as
// the rasterizer hands it on. Nothing when a factor is computed from the screen (an NDC: `* 2 - 1`,
// a viewport map, a divide by an interpolated w) or there is not exactly one such lane.
std::optional<PlainScreen> plainScreenFactor(Decomposer& d, SourceAnalysis& flow, Lane term, std::optional<Lane> besides,
                                             size_t& visits) {
  Factors f;
  collectFactors(d, flow, term, false, f, 0);
  visits += static_cast<size_t>(f.visits);
  if (f.tooLarge) return std::nullopt;
  std::optional<PlainScreen> plain;
  for (const auto& [factor, divides] : f.factors) {
    if (d.constant(factor) || d.uniformElement(factor)) continue;
    if (besides && factor == d.canonical(*besides)) continue;
    const Sources s = sourcesOf(flow, d, factor);
    if (!s.fragCoord && !s.varying && !s.texel && !s.other) continue;  // uniforms alone (a texture's size)
    if (screenReadAsItIs(s) && !divides && !plain) plain = PlainScreen{factor, s.fragCoord};
    else if (texelOnly(s)) continue;  // a depth factor the caller did not name
    else return std::nullopt;
  }
  return plain;
}

// One candidate: the pixel's coordinate (axis 0 or 1), the depth factor, the cbuffer element.
struct RayCandidate {
  Lane at, depth;
  uint32_t axis = 0;
  Coefficient scale;
  bool divides = false;
  Sources screen, depthSources;
  std::set<uint32_t> through;
  bool notNdc = false;  // the pixel's coordinate is a screen input read as it is
};

std::optional<RayCandidate> rayCandidate(Decomposer& d, SourceAnalysis& flow, Lane at, size_t& visits) {
  Factors f;
  collectFactors(d, flow, at, false, f, 0);
  visits += static_cast<size_t>(f.visits);
  if (f.through.empty() || f.tooLarge) return std::nullopt;
  RayCandidate c{at, {}, 0, {}, false, {}, {}, f.through, false};
  int screens = 0, depths = 0, scales = 0;
  for (const auto& [factor, divides] : f.factors) {
    if (d.constant(factor)) continue;
    if (auto element = d.uniformElement(factor)) {
      if (++scales > 1 || element->path.size() < 2) return std::nullopt;
      c.scale = *element;
      c.divides = divides;
      continue;
    }
    Sources s = sourcesOf(flow, d, factor);
    bool pixel = (s.fragCoord || s.varying) && !s.texel && !s.other;
    if (pixel && !divides && ((s.inputLanes & 3u) == 1u || (s.inputLanes & 3u) == 2u)) {
      if (++screens > 1) return std::nullopt;
      c.axis = (s.inputLanes & 3u) == 1u ? 0 : 1;
      c.screen = s;
      // Read as it is: a pixel position (and the element with it a screen size, not 1/P00), or a
      // texture coordinate that may carry a UV, NDC or a colour (`v1.x * texel * cb0[2].x` is a
      // tinted colour as often as a view ray): not taken, reported.
      c.notNdc = !s.arithmetic;
    } else if (texelOnly(s) && !divides) {
      if (++depths > 1) return std::nullopt;
      c.depth = factor;
      c.depthSources = s;
    } else {
      return std::nullopt;
    }
  }
  if (screens != 1 || depths != 1 || scales != 1) return std::nullopt;
  return c;
}

std::string scaleText(const spirv::Module& m, const RayCandidate& c) {
  std::string element = elementText(m, c.scale);
  if (element.empty()) return "";
  return c.divides ? "(1 / " + element + ")" : element;
}

std::vector<ComponentRay> findComponentRays(RegisterAnalyses& a) {
  const spirv::Module& registers = a.registers;
  SourceAnalysis& flow = a.flow;
  Decomposer& d = a.d;
  const LineMap& lines = a.lines;
  std::vector<RayCandidate> candidates;
  std::set<Lane> seen;
  size_t& visits = a.factorVisits;
  spirv::forEachFunctionInstruction(registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFMul && inst.opcode != spv::OpFDiv && inst.opcode != spv::OpVectorTimesScalar) return;
    const Instruction* type = registers.definition(inst.typeId);
    uint32_t count = type && type->opcode == spv::OpTypeVector ? type->operand(1) : 1;
    for (uint32_t lane = 0; lane < count; ++lane) {
      Lane at = d.canonical({inst.resultId, lane});
      if (!seen.insert(at).second) continue;
      if (auto c = rayCandidate(d, flow, at, visits)) candidates.push_back(std::move(*c));
    }
  });
  // The innermost product only: one computed from another candidate is per eye through it.
  std::erase_if(candidates, [&](const RayCandidate& c) {
    return std::any_of(candidates.begin(), candidates.end(),
                       [&](const RayCandidate& inner) { return &inner != &c && c.through.count(inner.at.id) && inner.axis == c.axis; });
  });
  std::vector<ComponentRay> found;
  for (const auto& c : candidates) {
    if (c.axis != 0) continue;
    // A position rebuild has its y from the same depth.
    bool hasY = std::any_of(candidates.begin(), candidates.end(),
                            [&](const RayCandidate& y) { return y.axis == 1 && y.depth == c.depth; });
    if (!hasY) continue;
    ComponentRay r;
    r.x = c.screen;
    r.depth = c.depthSources;
    r.fix.line = lines.lineOf(c.at.id);
    r.fix.lane = c.at.lane;
    r.fix.depthLine = lines.lineOf(c.depth.id);
    r.fix.depthLane = c.depth.lane;
    r.fix.scale = scaleText(registers, c);
    r.xId = c.at.id;
    if (c.notNdc)
      r.reason = "the pixel's x is a screen input read as it is: the pixel position (its element a screen size, not "
                 "1/P00), or a texture coordinate that may carry a UV, NDC or a colour; not known to be a view ray, "
                 "left for a person";
    else if (r.fix.scale.empty()) r.reason = "the projection scale is not a cbuffer element the source can name";
    else if (!r.fix.line || !r.fix.depthLine)
      r.reason = lines.present() ? "x or the depth is computed outside the main file (an #include or a macro)"
                                 : "the module has no source lines";
    found.push_back(std::move(r));
  }
  return found;
}

// The interpolated rays of `a` (InterpolatedRay): every product lane whose factors are one lane of a
// vector input read as it is, that input's z divided by, one texel-only depth, and uniforms or
// constants; one report per input and depth with lanes x, y and z.
std::vector<InterpolatedRay> findInterpolatedRays(RegisterAnalyses& a) {
  Decomposer& d = a.d;
  struct Seen {
    uint32_t lanes = 0, line = 0;
    Sources depth;
    // By the ray's input lane bit: the first product's line and lane, and the cbuffer element it is
    // scaled by ("" when not one element, not dividing).
    struct First {
      uint32_t line = 0;
      Lane at;
      std::string scale;
    };
    std::map<uint32_t, First> byLane;
  };
  std::map<std::pair<std::string, Lane>, Seen> byInputAndDepth;
  std::set<Lane> seen;
  spirv::forEachFunctionInstruction(a.registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFMul && inst.opcode != spv::OpVectorTimesScalar) return;
    const Instruction* type = a.registers.definition(inst.typeId);
    const uint32_t count = type && type->opcode == spv::OpTypeVector ? type->operand(1) : 1;
    for (uint32_t lane = 0; lane < count; ++lane) {
      const Lane at = d.canonical({inst.resultId, lane});
      if (!seen.insert(at).second) continue;
      Factors f;
      collectFactors(d, a.flow, at, false, f, 0);
      a.factorVisits += static_cast<size_t>(f.visits);
      if (f.tooLarge) continue;
      std::optional<Sources> ray, overZ, depth;
      std::optional<Lane> depthLane;
      std::vector<std::string> scales;
      bool other = false;
      for (const auto& [factor, divides] : f.factors) {
        if (d.constant(factor)) continue;
        if (auto element = d.uniformElement(factor)) {
          scales.push_back(divides ? "" : elementText(a.registers, *element));
          continue;
        }
        const Sources s = sourcesOf(a.flow, d, factor);
        const bool plainInput = screenReadAsItIs(s) && !s.fragCoord &&
                                std::popcount(s.inputLanes) == 1 && s.inputs.size() == 1;
        if (plainInput && !divides && !ray) ray = s;
        else if (plainInput && divides && s.inputLanes == 4u && !overZ) overZ = s;
        else if (texelOnly(s) && !divides && !depth) depth = s, depthLane = factor;
        else other = true;
      }
      if (other || !ray || !overZ || !depth || ray->inputs != overZ->inputs || ray->inputLanes > 4u) continue;
      Seen& entry = byInputAndDepth[{*ray->inputs.begin(), *depthLane}];
      entry.lanes |= ray->inputLanes;
      entry.depth = *depth;
      const uint32_t line = a.lines.lineOf(at.id);
      if (line && (!entry.line || line < entry.line)) entry.line = line;
      const Seen::First here{line, at, scales.size() == 1 ? scales[0] : ""};
      auto [it, inserted] = entry.byLane.try_emplace(ray->inputLanes, here);
      if (!inserted && line && (!it->second.line || line < it->second.line)) it->second = here;
    }
  });
  std::vector<InterpolatedRay> found;
  for (const auto& [key, entry] : byInputAndDepth) {
    if (entry.lanes != 7u) continue;
    InterpolatedRay r{key.first, entry.depth, entry.line, {}, ""};
    const Seen::First &x = entry.byLane.at(1u), &z = entry.byLane.at(4u);
    r.fix.lines = {x.line, z.line};
    r.fix.lanes = {x.at.lane, z.at.lane};
    r.fix.afterLine = std::max(x.line, z.line);
    r.fix.rayX = key.first + ".x";
    r.fix.rayZ = key.first + ".z";
    if (!x.scale.empty() && x.scale == z.scale) r.fix.farPlane = x.scale;
    else r.reason = "the ray is not scaled to depth 1 by one cbuffer element over its z (a full-screen pass's far "
                    "plane), which tells a full-screen pass's ray from a light volume's";
    if (r.reason.empty() && (!x.line || !z.line)) r.reason = "the position is computed outside the main file (an #include or a macro)";
    found.push_back(std::move(r));
  }
  return found;
}

}  // namespace

DecompiledForms findDecompiledForms(const spirv::Module& registers, bool hlsl, const std::string& mainFile) {
  RegisterAnalyses analyses(registers, hlsl, mainFile);
  DecompiledForms forms;
  forms.products = findRowProducts(analyses);
  forms.rays = findComponentRays(analyses);
  forms.interpolatedRays = findInterpolatedRays(analyses);
  forms.reprojections = findReprojections(analyses, forms.products, forms.rays);
  for (RowProduct& p : findBasisRays(analyses)) forms.products.push_back(std::move(p));
  // A screen-to-world product's x * z term is a product of the screen and the depth like a view ray's
  // x: one correction, the product's.
  std::erase_if(forms.rays, [&](const ComponentRay& r) {
    return std::any_of(forms.products.begin(), forms.products.end(),
                       [&](const RowProduct& p) { return p.scaledTerms.count({r.fix.line, r.fix.lane}) > 0; });
  });
  forms.work = analyses.d.computed() + analyses.factorVisits;
  return forms;
}

}  // namespace stereoshift::deferred
