// The per-eye-view pass's fix, apart from its decision (per_eye_view_pass.cpp): where the world-space
// offset of this eye's centre comes from (an inverse view-projection by name, the matrices that take
// the same world point to the clip position, or eye-offset parameters the application fills), and
// the rewrite of every load of the camera into `loaded + offset`.
#pragma once

#include "passes/analysis/clip_positions.h"
#include "passes/analysis/uniform_slots.h"
#include "passes/ir/module.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

struct PassContext;

namespace per_eye_view {

// `C - P` / `P - C` with C a vec3/vec4 uniform slot (or the .xyz of one) and P varying; for the
// tutorial form (the camera passed on as it is) a point written to an output, with no subtraction.
struct Subtraction {
  uint32_t id = 0;     // the OpFSub (0: none)
  uint32_t point = 0;  // P
};

struct OffsetSource {
  enum Kind { InverseViewProjection, InvertedClipMatrices, EyeOffsetParams } kind = EyeOffsetParams;
  std::vector<analysis::Slot> matrices;  // InverseViewProjection: one; InvertedClipMatrices: product order
  bool columnVectors = true;   // the shader writes M * v (true) or v * M (false, HLSL mul(M, v))
  std::string description;     // the formula, for the report
};

// The matrices that take a point to the clip position: gl_Position = M_k * ... * M_1 * W (or
// W * M_1 * ... * M_k), each a uniform matrix (a slot) or a product of them. Every W along the
// way is a candidate: `VP * (Model * p)` offers both `Model * p` (world) and `p` (object space).
struct ClipChain {
  bool columnVectors = true;
  std::vector<std::vector<analysis::Slot>> factors;  // outermost first
  std::vector<uint32_t> points;                      // points[i]: the vector factors[i] multiplies

  // The product that takes points[level] to the clip position, in multiplication order.
  std::vector<analysis::Slot> productFor(size_t level) const;
};

// Clip chains of every store to a clip position in the folded module `f`.
std::vector<ClipChain> clipChains(const std::vector<ClipPosition>& positions, const spirv::Module& f);

// The points a vertex shader writes to its non-built-in outputs: `FragPos`, `TBN * FragPos` (the
// frame taken off). Where the camera goes to an output as it is, these say which space it lives in.
std::vector<Subtraction> pointsWrittenToOutputs(const spirv::Module& m);

// Where the offset of the camera `camera`, subtracted from the points `subs`, comes from.
OffsetSource chooseOffsetSource(const PassContext& ctx, const spirv::Module& f, const analysis::Slot& camera,
                                const std::vector<Subtraction>& subs, const std::vector<ClipChain>& chains);

// Rewrites every load of `camera` (the whole vector or one component) in the context's module into
// `loaded + offset`; returns how many loads were rewritten.
int rewriteCameraLoads(PassContext& ctx, const analysis::Slot& camera, const OffsetSource& source);

}  // namespace per_eye_view
}  // namespace stereoshift
