// The halo pass's part for decompiled HLSL (halo_moved_lanes.cpp): this turns the lanes of vertex
// outputs computed from the clip position's x through registers (a 3Dmigoto dump's `r0.xz =
// float2(0.5,0.5) * r1.xw; o3.xy = r0.xw + r0.zz;`: Unity's screen position, read by soft particles,
// water and refraction) into ones that move with the shifted position.
//
// The decompiler writes its registers lane by lane and over and over, so the module's own data flow
// (halo_pass.cpp) sees no value of the position in such an output. The register copy
// (AnalysisManager::registerSsaCopy: every register write its own value) shows each lane of an
// output as a sum of terms (deferred_unprojection/linear_form.h). Where the position's x is one of
// them with a constant coefficient a, and no other term depends on it, the stereo lane is the mono
// one plus a * (shifted x - x): exact, whatever else the lane adds (the w, a constant, a texcoord).
// A coefficient from a cbuffer, a product of x with itself, or an x inside an opaque term is left
// alone (the output keeps its mono value, as before).
#pragma once

#include "passes/pass.h"

#include <string>
#include <vector>

namespace stereoshift {

// Moves such lanes in the module (after the output's store, where the position's store is in the
// same block) and records them (HaloFacts::movedLanes) for the HLSL splice. `fixed`: outputs the
// halo pass already shifted. HLSL sources only (the register copy is made for nothing else); true
// when a lane was moved.
bool moveLanesDerivedFromPositionX(PassContext& ctx, const std::vector<std::string>& fixed);

}  // namespace stereoshift
