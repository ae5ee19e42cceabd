// deferred-unprojection's basis form: turns a decompiled HLSL pixel shader's position rebuilt as a
// ray times the depth, the ray a sum of cbuffer basis vectors times the pixel's x and y plus one
// (CryEngine's `(vWBasisX * x + (vWBasisY * y + vWBasisZ)) * depth + cameraPos`, spelled
// `r3.xyz = cb0[1].xyz * r2.yyy; r3.xyz = r2.xxx * cb0[0].xyz + r3.xyz; r3.xyz = cb0[2].xyz + r3.xyz;
// r2.xyz = r3.xyz * r1.xxx + cb0[3].xyz;`), into the screen-to-world form's RowProduct: it is that
// map, M = (basis x, basis y, basis z, camera), applied in another order, and takes the same
// correction, q -= M[column of x] * s.x * (|z| - s.y) * sign(z), with z the depth the ray is scaled
// by. The linear forms see the ray times the depth as one opaque term, so the ray is looked into
// here.
#include "passes/deferred_unprojection/register_analyses.h"

#include <map>

namespace stereoshift::deferred {

namespace {

// One component of a candidate: p = ray * depth (+ camera), ray = bx * x + by * y + bz.
struct BasisComponent {
  Lane at, depth, x, y;
  Coefficient bx, by, bz;
  uint32_t index = 0;  // the lane the basis vectors' elements share: which component of p this is
};

bool element(const Coefficient& c) { return c.uniform() && c.path.size() >= 2 && c.scale == 1.0f; }

// The vector a basis element is a lane of.
std::string vectorKey(const Coefficient& c) { return pathKey(c.root, c.path, c.path.size() - 1); }

// The ray's parts: the pixel's x and y (lanes 0 and 1 of one screen input, no texel) each times a
// basis element, and one basis element on its own; all three elements lane `index` of their vectors.
std::optional<BasisComponent> rayOf(RegisterAnalyses& a, Lane ray) {
  const Linear& f = a.d.form(ray);
  if (f.size() != 3) return std::nullopt;
  BasisComponent c;
  bool x = false, y = false, z = false;
  for (const Part& part : f) {
    if (!element(part.coefficient)) return std::nullopt;
    if (!part.term) {
      if (z) return std::nullopt;
      z = true, c.bz = part.coefficient;
      continue;
    }
    const Sources s = sourcesOf(a.flow, a.d, *part.term);
    if (!(s.fragCoord || s.varying) || s.texel || s.other) return std::nullopt;
    if ((s.inputLanes & 3u) == 1u && !x) x = true, c.x = *part.term, c.bx = part.coefficient;
    else if ((s.inputLanes & 3u) == 2u && !y) y = true, c.y = *part.term, c.by = part.coefficient;
    else return std::nullopt;
  }
  if (!x || !y || !z) return std::nullopt;
  c.index = c.bx.path.back();
  if (c.by.path.back() != c.index || c.bz.path.back() != c.index) return std::nullopt;
  return c;
}

// A lane that is one product (times 1) of a ray and a texel-only depth, plus at most one cbuffer
// element (the camera).
std::optional<BasisComponent> componentOf(RegisterAnalyses& a, Lane at, std::string& key) {
  Decomposer& d = a.d;
  const Linear& f = d.form(at);
  if (f.empty() || f.size() > 2) return std::nullopt;
  std::optional<Lane> product;
  std::string camera;
  for (const Part& part : f) {
    if (part.term && !part.coefficient.uniform() && part.coefficient.scale == 1.0f && !product) product = *part.term;
    else if (!part.term && element(part.coefficient) && camera.empty()) camera = vectorKey(part.coefficient);
    else return std::nullopt;
  }
  if (!product) return std::nullopt;
  const Instruction* def = d.definition(product->id);
  if (!def || def->operands.size() != 2 || (def->opcode != spv::OpFMul && def->opcode != spv::OpVectorTimesScalar))
    return std::nullopt;
  auto laneOf = [&](uint32_t id) { return d.canonical({id, d.isVector(id) ? product->lane : 0}); };
  const Lane first = laneOf(def->operand(0)), second = laneOf(def->operand(1));
  const bool firstDepth = texelOnly(sourcesOf(a.flow, d, first)), secondDepth = texelOnly(sourcesOf(a.flow, d, second));
  if (firstDepth == secondDepth) return std::nullopt;
  auto c = rayOf(a, firstDepth ? second : first);
  if (!c) return std::nullopt;
  c->at = at;
  c->depth = firstDepth ? first : second;
  key = vectorKey(c->bx) + "|" + vectorKey(c->by) + "|" + vectorKey(c->bz) + "|" + camera + "|" +
        std::to_string(c->depth.id) + "." + std::to_string(c->depth.lane) + "|" + std::to_string(c->x.id) + "|" +
        std::to_string(c->y.id);
  return c;
}

// The RowProduct of components 0-2 (the point has no w: the map is affine).
RowProduct productOf(RegisterAnalyses& a, const std::map<uint32_t, BasisComponent>& components) {
  Decomposer& d = a.d;
  const BasisComponent& any = components.begin()->second;
  RowProduct p;
  p.x = sourcesOf(a.flow, d, any.x);
  p.y = sourcesOf(a.flow, d, any.y);
  p.z = sourcesOf(a.flow, d, any.depth);
  p.fix.scaledByDepth = true;
  p.fix.basisRay = true;
  p.fix.present = {true, true, true, false};
  p.fix.depthLine = a.lines.lineOf(any.depth.id);
  p.fix.depthLane = any.depth.lane;
  // The coordinate's scale as in the screen-to-world form: the depth's UV, or from the map.
  const bool notNdc = notKnownNdc(d, a.flow, any.x), uv = notNdc && depthSampledAt(d, any.depth, any.x, any.y);
  p.fix.uvOfTheDepthTexture = uv;
  p.fix.scaleFromTheMatrix = notNdc && !uv;
  std::set<std::string> vectors;
  for (const auto& [i, c] : components) {
    const std::string column = elementText(a.registers, c.bx);
    p.fix.column[i] = uv && !column.empty() ? "(0.5 * " + column + ")" : column;
    p.fix.columnZ[i] = elementText(a.registers, c.bz);
    p.fix.columnY[i] = elementText(a.registers, c.by);
    p.fix.lines[i] = a.lines.lineOf(c.at.id);
    p.fix.lanes[i] = c.at.lane;
    p.fix.afterLine = std::max(p.fix.afterLine, p.fix.lines[i]);
    for (const Coefficient* e : {&c.bx, &c.by, &c.bz}) {
      Coefficient vector = *e;
      vector.path.pop_back();
      vectors.insert(elementText(a.registers, vector));
    }
    if (column.empty() || p.fix.columnZ[i].empty() || p.fix.columnY[i].empty()) p.reason = "a basis element is not a cbuffer element the source can name";
    else if (!p.fix.lines[i] && p.reason.empty())
      p.reason = a.lines.present() ? "a component is computed outside the main file (an #include or a macro)"
                                   : "the module has no source lines";
  }
  for (const std::string& v : vectors) p.rows += (p.rows.empty() ? "" : ", ") + v;
  if (!p.fix.depthLine && p.reason.empty()) p.reason = "the depth is computed outside the main file (an #include or a macro)";
  return p;
}

}  // namespace

std::vector<RowProduct> findBasisRays(RegisterAnalyses& a) {
  std::map<std::string, std::map<uint32_t, BasisComponent>> groups;
  std::set<Lane> seen;
  spirv::forEachFunctionInstruction(a.registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFAdd && inst.opcode != spv::OpFMul && inst.opcode != spv::OpVectorTimesScalar) return;
    const uint32_t count = a.d.lanes(inst.resultId);
    for (uint32_t lane = 0; lane < count && lane < 4; ++lane) {
      const Lane at = a.d.canonical({inst.resultId, lane});
      if (at.id != inst.resultId || !seen.insert(at).second) continue;
      std::string key;
      if (auto c = componentOf(a, at, key)) groups[key].emplace(c->index, *c);  // the first value of each
    }
  });
  std::vector<RowProduct> found;
  for (const auto& [key, components] : groups)
    if (components.count(0) && components.count(1) && components.count(2) && components.size() == 3)
      found.push_back(productOf(a, components));
  return found;
}

}  // namespace stereoshift::deferred
