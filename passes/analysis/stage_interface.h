// The stage interface as the next stage links to it, and the next-stage facts: how a stage uses
// its inputs (which feed texture coordinates, as a direction or as one side of a subtraction), so
// that the stage before it can tell a view vector it writes for relief mapping from one written for
// shading (next_stage_facts.h). Computed by the analysis manager (stageInputUses) on the folded copy.
#pragma once

#include "passes/analysis/view_vector_flow.h"
#include "passes/ir/module.h"
#include "passes/next_stage_facts.h"
#include "core/shader.h"

#include <cstdint>
#include <optional>
#include <string>

namespace stereoshift::analysis {

// One input or output as the other stage links to it: a loose variable, or a member of a block.
struct InterfaceSlot {
  std::string name;       // the variable's name, or the member's
  std::string blockName;  // the block type's name, for a member
  std::string display;    // for the report: `vs_out.TangentViewPos`
  std::optional<uint32_t> location;
  bool builtin = false;
};
InterfaceSlot interfaceSlot(const spirv::Module& m, uint32_t variable, int64_t member);

// The next stage's use of one of this stage's outputs, if the facts say.
const StageInputUse* consumerOf(const NextStageFacts* next, const spirv::Module& m, const OutputSlot& output);

// How the stage of `module` uses its inputs. `folded` and `flow`: its folded copy and the view-vector
// flow on it (null: the inputs are listed, none analysed). `consumer`: for a stage between
// (geometry, tessellation), the facts of the stage after it: each input then gets the uses of the
// outputs it is written to.
NextStageFacts describeStageInputUses(const spirv::Module& module, const spirv::Module* folded, ViewVectorFlow* flow,
                                      const SourceInfo& source, const std::string& file,
                                      const NextStageFacts* consumer);

// Whether the module subtracts vec3/vec4 values anywhere: a view vector (`camera - P`) needs one, and
// inlining and folding never create one, so without it per-eye-view has nothing to look at.
bool hasVectorSubtraction(const spirv::Module& module);

// Whether a pre-rasterization module reads a value that could be the camera position passed on to
// the next stage as it is (a vec3/vec4 uniform, a whole uniform struct, the inverse of a matrix):
// the tutorial form of relief mapping, `TangentViewPos = TBN * viewPos`, has no subtraction there.
bool passesCameraCandidate(const spirv::Module& module);

}  // namespace stereoshift::analysis
