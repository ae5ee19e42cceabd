// What the decompiled-HLSL recognisers (row_products.cpp, basis_rays.cpp) share: the register
// copy's analyses, built once, and what they ask of a screen coordinate and of a depth.
#pragma once

#include "passes/deferred_unprojection/linear_form.h"
#include "passes/deferred_unprojection/row_products.h"
#include "passes/deferred_unprojection/sources.h"

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace stereoshift::deferred {

using namespace linear;

// A key naming the uniform a coefficient's path leads to, its first `length` steps: "5/0/20".
inline std::string pathKey(uint32_t root, const AccessPath& path, size_t length) {
  std::string key = std::to_string(root);
  for (size_t k = 0; k < length && k < path.size(); ++k) key += "/" + std::to_string(path[k]);
  return key;
}

// One component of a candidate q: linear in three terms with a uniform element as each
// coefficient, plus one uniform element; which component it is (`index`, 0-3) and of which matrix
// (`matrix`) the elements say. Column storage (`mad` chains: `r1.xyzw = r0.xxxx * cb1[20].xyzw +
// ...`): every element of component i is lane i of a column vector. Row storage (dp4: `r1.x =
// dot(r0.xyzw, cb1[20].xyzw)`): every element of component i is in row vector k+i of one array.
struct Member {
  Lane at;
  std::map<Lane, Coefficient> byTerm;
  Coefficient translation;
  uint32_t index = 0;
  std::string matrix;  // the key of the matrix the elements belong to
};

// The register copy's analyses both forms read, built once.
struct RegisterAnalyses {
  const spirv::Module& registers;
  ValueFlow index;
  SourceAnalysis flow;
  Decomposer d;
  LineMap lines;
  size_t factorVisits = 0;
  // findRowProducts' candidates (every lane that is one component of a product, in module order)
  // and, of them, the products whose terms are not a pixel and a depth (a point computed in the
  // shader: a re-projection, a light-space transform), for findReprojections.
  std::vector<Member> members;
  std::vector<std::array<const Member*, 4>> otherProducts;
  RegisterAnalyses(const spirv::Module& m, bool hlsl, const std::string& mainFile)
      : registers(m), index(m), flow(index, hlsl, {}), d(index), lines(m, mainFile) {}
};

// A depth read from a texture and nothing else per pixel.
inline bool texelOnly(const Sources& s) { return s.texel && !s.fragCoord && !s.varying && !s.other; }


// A screen input (gl_FragCoord / SV_Position, or another fragment input) read as the rasterizer
// hands it on: moved, not computed, and made from nothing else.
inline bool screenReadAsItIs(const Sources& s) { return (s.fragCoord || s.varying) && !s.arithmetic && !s.texel && !s.other; }

// Whether a pixel coordinate term is a screen input read as it is or times one constant or uniform,
// or over (or times) a value of uniforms alone (a pixel position over a texture's size: a UV; a
// perspective divide by an input's w is NDC).
inline bool notKnownNdc(Decomposer& d, SourceAnalysis& flow, Lane term) {
  const Linear& f = d.form(term);
  if (f.size() != 1 || !f[0].term) return false;
  const Lane inner = *f[0].term;
  Sources s = sourcesOf(flow, d, inner);
  if ((s.fragCoord || s.varying) && !s.arithmetic) return true;
  const Instruction* def = d.definition(inner.id);
  if (!def || (def->opcode != spv::OpFDiv && def->opcode != spv::OpFMul) || def->operands.size() != 2) return false;
  auto laneOf = [&](uint32_t id) { return Lane{id, d.isVector(id) ? inner.lane : 0}; };
  const Sources a = sourcesOf(flow, d, laneOf(def->operand(0))), b = sourcesOf(flow, d, laneOf(def->operand(1)));
  auto uniformOnly = [](const Sources& x) { return !x.fragCoord && !x.varying && !x.texel && !x.other; };
  return (screenReadAsItIs(a) && uniformOnly(b)) || (def->opcode == spv::OpFMul && screenReadAsItIs(b) && uniformOnly(a));
}

// The coordinate of the one image sample the depth `z` is computed from (z itself, or z made linear
// from it), or nothing when there is none or more than one.
inline std::optional<uint32_t> depthSampleCoordinate(Decomposer& d, Lane z) {
  std::optional<uint32_t> coordinate;
  int samples = 0;
  std::set<uint32_t> seen;
  std::vector<std::pair<uint32_t, int>> stack{{d.canonical(z).id, 0}};
  while (!stack.empty()) {
    auto [id, depth] = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) continue;
    const Instruction* def = d.definition(id);
    if (!def) continue;
    switch (def->opcode) {
      case spv::OpImageSampleImplicitLod: case spv::OpImageSampleExplicitLod: case spv::OpImageGather:
        if (def->operands.size() >= 2) coordinate = def->operand(1);
        ++samples;
        continue;
      default: break;
    }
    if (depth >= 12) continue;
    for (uint32_t operand : def->operands)
      if (d.definition(operand)) stack.push_back({operand, depth + 1});
  }
  return samples == 1 ? coordinate : std::nullopt;
}

// Whether `screenX` and `screenY` (the pixel's coordinates as the product reads them: the lanes, or
// the one term each is) are the coordinate the depth `z` is sampled at: then they run over [0, 1]
// across the screen-sized depth buffer, a UV whose NDC is 2u - 1.
inline bool depthSampledAt(Decomposer& d, Lane z, Lane screenX, Lane screenY) {
  const std::optional<uint32_t> coordinate = depthSampleCoordinate(d, z);
  if (!coordinate) return false;
  auto is = [&](Lane term, uint32_t lane) {
    const Lane at = d.canonical({*coordinate, lane});
    if (d.canonical(term) == at) return true;
    const Linear& f = d.form(term);
    return f.size() == 1 && f[0].term && !f[0].coefficient.uniform() && f[0].coefficient.scale == 1.0f &&
           d.canonical(*f[0].term) == at;
  };
  return is(screenX, 0) && is(screenY, 1);
}

// The cbuffer vectors a product's components read, as the source names them, in numeric order.
std::string rowsText(const spirv::Module& m, const std::array<const Member*, 4>& q);

// The re-projections (reprojections.cpp), among the products findRowProducts found with other terms
// (a.otherProducts), of points computed from the fixed ones of `rebuilds` or from the view-space x a
// fixed per-component view ray of `rays` corrects.
std::vector<Reprojection> findReprojections(RegisterAnalyses& a, const std::vector<RowProduct>& rebuilds,
                                            const std::vector<ComponentRay>& rays);

// The basis form (basis_rays.cpp): a position rebuilt as (bx * x + by * y + bz) * depth (+ camera)
// over cbuffer basis vectors, as the screen-to-world form's RowProduct.
std::vector<RowProduct> findBasisRays(RegisterAnalyses& a);

}  // namespace stereoshift::deferred
