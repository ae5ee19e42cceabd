// Completing and checking a pipeline before `verify` runs it: a tessellation-evaluation or geometry
// shader handed over without the stages in front of it gets pass-through ones synthesized from
// its own inputs (a vertex shader, and a tessellation-control shader for a lone tese), and the
// interface between consecutive stages is checked so that a pipeline the driver would refuse
// is reported by location and name instead of as a failed vkCreateGraphicsPipelines.
#pragma once

#include "core/result.h"
#include "passes/ir/module.h"

#include <string>
#include <vector>

namespace stereoshift::harness {

// One user-defined varying as the stages see it: per-vertex arrays of tessellation / geometry
// stages are stripped to their element, block members are listed one by one.
struct InterfaceSlot {
  uint32_t location = 0;
  uint32_t component = 0;
  uint32_t type = 0;  // the (element) type id in its module
  std::string name;
  bool patch = false;
};

// The user-defined (non-built-in) inputs or outputs of the module's entry point.
std::vector<InterfaceSlot> interfaceSlots(const spirv::Module& module, spv::StorageClass storage);

// GLSL source of the type (`vec3`, `dmat4`, `ivec2[3]`); empty when it has no GLSL spelling as a
// varying (bool, 8/16-bit, structs, arrays of arrays).
std::string glslTypeName(const spirv::Module& module, uint32_t type);

// The stages that must run in front of `first` (the earliest stage given) for it to run: nothing
// for a vertex shader, a pass-through vertex shader for tessellation control and geometry, a
// vertex and a tessellation-control shader for tessellation evaluation. Each synthesized vertex
// shader reads one vec4 attribute (location 0) and derives every output from it, so distinct
// varyings get distinct, plausible values. The error when an input cannot be produced.
struct LeadingStages {
  std::vector<spirv::Module> modules;  // in pipeline order
  std::vector<std::string> names;      // one per module, for the report
};
Result<LeadingStages> synthesizeLeadingStages(const spirv::Module& first);

// Every input of stage `next` at a location must be written by `previous` with a type of the same
// GLSL spelling; the error says which one is not (stage names, location, variable names, types).
Status checkStageInterface(const spirv::Module& previous, const spirv::Module& next);

// The control points per patch the tessellation stages of this pipeline use: the tesc's
// OutputVertices where there is one, else what the synthesized tesc declares.
uint32_t patchControlPoints(const std::vector<spirv::Module>& stages);

const char* executionModelName(spv::ExecutionModel model);

}  // namespace stereoshift::harness
