// deferred-unprojection's cbuffer-row form: turns a decompiled HLSL pixel shader's position rebuild,
// `InvM * float4(ndc, depth, 1)` spelled over the four float4 rows of a cbuffer array
// (3Dmigoto's decompiler: `r1.xyzw = r0.yyyy * cb1[21].xyzw; r1.xyzw = r0.xxxx * cb1[20].xyzw +
// r1.xyzw; ... + cb1[23].xyzw` or `r1.x = dot(r0.xyzw, cb1[20].xyzw); r1.y = ...`), into a found
// unprojection with the source lines that compute each component of q and InvM's column of NDC x
// as the source names it, for the fix the text carries (RowProductTextFix).
//
// It runs on the register copy (AnalysisManager::registerSsaCopy(): the decompiler reuses each
// register r0..rN for many values, and only SSA form tells them apart) with glslang's OpLine per
// statement. A float4 q is one when each component is linear in the same three per-pixel values
// with a single uniform element as each coefficient and one uniform element as its constant:
//     q[i] = M[i][0]*a + M[i][1]*b + M[i][2]*c + M[i][3]
// and, as for the matrix form (deferred_unprojection_pass.cpp), a is the pixel's x (from
// SV_Position's or a vector input's lane 0, no texel), b its y (lane 1), c a depth read from a
// texture. Coefficients are found through sums, differences, negations, `mad`/fma, dp2-dp4 and
// products with a uniform element or a constant; a product of two per-pixel values, or of two
// uniform elements, is an opaque value (a term), never looked into.
#pragma once

#include "passes/deferred_unprojection/sources.h"
#include "passes/run_record.h"

#include <array>
#include <set>
#include <string>
#include <vector>

namespace stereoshift::deferred {

struct RowProduct {
  RowProductTextFix fix;  // the lines of q's components and the column of NDC x
  Sources x, y, z;        // what the pixel's x, y and the depth are computed from
  std::string rows;       // the uniform vectors holding the matrix, as the source names them
  std::string reason;     // empty when every component has a line of the main file
  // The same product applied to an interpolated position (lanes x, y, z of one input, no texel):
  // a light-space transform for a shadow-map or projector lookup (or a screen-space one), never
  // fixed, reported so a person knows it was seen.
  bool interpolated = false;
  // View vectors from a camera position to the rebuilt position (CameraTextFix), when q is.
  std::vector<CameraTextFix> cameras;
  // The screen-to-world form: the statements (line, lane) computing its x * z and y * z terms,
  // which are not view rays of their own.
  std::set<std::pair<uint32_t, uint32_t>> scaledTerms;
  // The register copy's values of q's components (0 where the shader does not compute one) and of
  // the depth: what a re-projection of the rebuilt point is traced back to (findReprojections).
  std::array<uint32_t, 4> qIds{};
  uint32_t depthId = 0;
};

// A re-projection of a point computed from a corrected rebuild, `clip = VP * (p, 1)` over cbuffer
// rows, whose clip x reaches the coordinate of a read of the rebuild's depth texture (SSAO's
// samples, a screen-space reflection's march): a lookup in this eye's image, which must land where
// this eye's image has the point, clip.x + s.x * (clip.w - s.y) in the re-projection's own units
// (ReprojectionTextFix).
struct Reprojection {
  ReprojectionTextFix fix;
  std::string rows;     // VP's vectors, as the source names them
  std::string texture;  // the depth texture it reads again
  std::string reason;   // empty when the text can carry it
};

// The view-ray form spelled per component (decompiled HLSL): a scalar x that is a product of the
// pixel's NDC x (lane 0 of SV_Position or a vector input, no texel), one depth factor (computed
// from a texel, no per-pixel input), one cbuffer element (k = 1/P00, or P00 divided by) and
// constants; a position rebuild has its y the same way (the pixel's y, the same depth factor), and
// an x without such a y is not taken (a texture coordinate scaled by a texel and a strength is
// not a position). The innermost such product is the fix point: later scalings of it are per eye
// through it.
struct ComponentRay {
  ViewRayTextFix fix;
  Sources x, depth;
  uint32_t xId = 0;  // the register copy's value of x (findReprojections)
  std::string reason;  // empty when x and the depth have lines of the main file
};

// A position rebuilt from a ray the vertex shader interpolates, scaled to depth 1 by its own z
// (Unity's `i.ray * (_ProjectionParams.z / i.ray.z) * Linear01Depth(d)`): lanes x, y and z of one
// vector input, each times one over that input's z, a depth made from a texel, and uniforms or
// constants. Never fixed: the ray's 1/P00, and whether the vertex shader's vertices were moved
// (a light volume) or not (a full-screen quad the cutoff keeps mono), are not in the pixel shader,
// and the correction differs between them. Reported, so a person knows where to look.
struct InterpolatedRay {
  std::string input;  // the vector input: "v2"
  Sources depth;
  uint32_t line = 0;  // the first statement computing a lane of the product
  InterpolatedRayTextFix fix;
  std::string reason;  // empty when the text can carry the full-screen pass's correction
};

// Both forms of one shader.
struct DecompiledForms {
  std::vector<RowProduct> products;
  std::vector<ComponentRay> rays;
  std::vector<InterpolatedRay> interpolatedRays;
  std::vector<Reprojection> reprojections;
  // Lanes decomposed, parts built and factors visited: linear in the shader's size, whatever its
  // shape (the complexity tests count it).
  size_t work = 0;
};

// Whether the module has uniform data an unprojection could be held in as rows: a uniform block
// member that is an array of float4 (a decompiled cbuffer). Cheap; spares other shaders the copy.
bool hasCbufferRows(const spirv::Module& m);

// Every cbuffer-row unprojection and per-component view ray of `registers` (the register copy,
// with OpLine), once each, on one index of it; lines count in `mainFile`, the name the front end
// gave the input's text.
DecompiledForms findDecompiledForms(const spirv::Module& registers, bool hlsl, const std::string& mainFile);

}  // namespace stereoshift::deferred
