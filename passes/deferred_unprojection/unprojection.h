// deferred-unprojection's constructs and their rewrites, apart from the pass's decision
// (deferred_unprojection_pass.cpp, whose opening comment has the maths): the matrix products that
// rebuild a position from depth, the `ray * depth` view-ray form, how each is recognised, and the
// code that makes each per eye.
#pragma once

#include "passes/deferred_unprojection/sources.h"
#include "passes/ir/module.h"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace stereoshift {

struct PassContext;

namespace deferred {

// One recognised unprojection, or the reason a matrix product is not one.
struct Product {
  spirv::Function* function = nullptr;
  uint32_t result = 0;
  bool vectorTimesMatrix = false;  // HLSL mul(M, v): v * M in SPIR-V, M's columns are HLSL rows
  uint32_t matrix = 0, vector = 0;
  Sources matrixSources, x, y, z, w, vectorSources;
  bool recognised = false;
  std::string reason;
};

// Where the view-ray fix takes the projection's x scale P00 from.
enum class ScaleKind {
  None,
  Injected,           // none in the shader: the injected eye parameter projScaleX, set by the application
  InverseElement,     // the uniform inverse projection that makes the ray: 1/P00 = InvP[0][0]
  ProjectionElement,  // a uniform projection (re-projecting the position, or read at [0][0]): P00 = P[0][0]
};

struct ProjectionScale {
  ScaleKind kind = ScaleKind::None;
  uint32_t matrixValue = 0;  // InverseElement: the loaded matrix, in the fix point's function
  uint32_t root = 0;         // ProjectionElement: the uniform variable and the path to the matrix
  AccessPath path;
  std::string name;
};

// One `ray * depth` product that rebuilds a view-space position.
struct RayProduct {
  spirv::Function* function = nullptr;
  uint32_t product = 0;   // the OpVectorTimesScalar
  uint32_t fixPoint = 0;  // the product, or the last scaling of it by values without a texel
  uint32_t components = 0;
  bool interpolated = false;  // the ray is an input varying, not made in this shader
  Sources ray, depth;
  std::string form;
  ProjectionScale scale;
};

// Fills p's sources and decides whether it is an unprojection (p.recognised) or why not (p.reason).
void classify(SourceAnalysis& flow, Product& p);
// Every `ray * depth` product whose vector is a view ray and whose scalar a depth read back;
// products computed from an already fixed unprojection (`fixedResults`) are skipped.
std::vector<RayProduct> findViewRays(spirv::Module& m, const ValueFlow& index, SourceAnalysis& flow,
                                     const std::set<uint32_t>& fixedResults);
// The projection's x scale for a view ray, from what the shader already has.
void findProjectionScale(const ValueFlow& index, SourceAnalysis& besidesFixes, const std::vector<Product>& products,
                         RayProduct& r);
// Computed from uniform data only.
bool isUniformOnly(const Sources& s);

// The rewrites (the context's eye parameters declared): q' for an unprojection, p.x' for a view
// ray, the shift for a re-projection of a corrected position.
void rewrite(PassContext& ctx, const Product& p);
void rewriteRay(PassContext& ctx, const RayProduct& r);
void rewriteReprojection(PassContext& ctx, const Product& p);

}  // namespace deferred
}  // namespace stereoshift
