// The per-eye-view pass's analyses that a pipeline runs on another stage (see next_stage_facts.h).
#pragma once

#include "passes/next_stage_facts.h"

namespace stereoshift {

namespace spirv {
class Module;
}
struct PassContext;

// Analyses the inputs of a (fragment) stage: which ones feed texture coordinates. Reads only the
// shared folded copy of the context's module; changes nothing.
NextStageFacts analyseStageInputs(PassContext& context);

// The same facts for a stage between (geometry, tessellation) whose outputs the context's nextStage
// describes: each input gets the uses of the outputs it is written to, so a vertex shader learns
// what the fragment stage does with a view vector a geometry stage passes on.
NextStageFacts carryStageFacts(PassContext& context);

// Whether the module subtracts vec3/vec4 values anywhere: a view vector (`camera - P`) needs one, and
// inlining and folding never create one, so without it per-eye-view has nothing to look at.
bool hasVectorSubtraction(const spirv::Module& module);

// Whether a pre-rasterization module reads a value that could be the camera position passed on to
// the next stage as it is (a vec3/vec4 uniform, a whole uniform struct, the inverse of a matrix):
// the tutorial form of relief mapping, `TangentViewPos = TBN * viewPos`, has no subtraction there.
bool passesCameraCandidate(const spirv::Module& module);

}  // namespace stereoshift
