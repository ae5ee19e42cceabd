// View-vector flow: per-eye-view's questions about one (folded) module, as thin queries on the
// forward engine of the shared value flow (value_flow.h): what varies per vertex / pixel, and where
// a value derived from some seeds goes, tagged on the way when it becomes a direction (normalize,
// reflect/refract, v.xy / v.z), a tangent-space vector (times a tangent frame), or a texture
// coordinate moved along a direction (`uv +- f(v)`: relief and parallax mapping).
//
// The analysis manager builds one on the folded copy and keeps it while the copy lives; the
// per-eye-view pass and the next-stage facts of a pipeline share it.
#pragma once

#include "passes/analysis/value_flow.h"
#include "passes/ir/module.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace stereoshift::analysis {

enum Flow : uint8_t {
  kDerived = 1,    // computed from the seed
  kDirection = 2,  // ... after it became a direction
  kTangent = 4,    // ... after it was multiplied by a tangent frame
  kOffset = 8,     // a texture coordinate moved along a direction from it: `uv +- f(v)`
};

// An output by where it is written: the variable, and the member of an interface block (or -1).
struct OutputSlot {
  uint32_t variable = 0;
  int64_t member = -1;
  bool operator<(const OutputSlot& o) const { return std::tie(variable, member) < std::tie(o.variable, o.member); }
};

class ViewVectorFlow {
 public:
  explicit ViewVectorFlow(const spirv::Module& m) : m_(m), flow_(m) {}
  ViewVectorFlow(const ViewVectorFlow&) = delete;
  ViewVectorFlow& operator=(const ViewVectorFlow&) = delete;

  const spirv::Module& module() const { return m_; }
  const ValueFlow& valueFlow() const { return flow_; }

  // An Input / Output variable of block type (`out VS_OUT { ... } vs_out;`): linked member by member.
  bool isInterfaceBlock(uint32_t variable) const;
  // Whether `id` varies per vertex / pixel: it is computed from a stage input (through arithmetic,
  // phis and function-local or private variables). Memoized: one propagation per module.
  bool dependsOnInput(uint32_t id);
  // A tangent frame: a matrix built in the shader from per-vertex vectors (`mat3(t, b, n)`,
  // possibly transposed) or an interpolated matrix input.
  bool isTangentFrame(uint32_t matrix);

  struct Sinks {
    uint8_t texcoord = 0;                    // flags seen at texture-coordinate operands
    std::map<OutputSlot, uint8_t> outputs;   // output (member) -> flags of what is stored to it
    std::set<uint32_t> subtractions;         // vec3/vec4 `a - b` with a from the seeds, b varying otherwise
    bool anyUse = false;                     // the seed reaches any other instruction
  };
  // Follows the seeds forward to a fixed point. Seeds are values, or variables (their loads).
  // `throughSamples`: a texel fetched at a derived coordinate counts as derived too (for "what
  // changes", not for "what is a view vector").
  Sinks follow(const std::map<uint32_t, uint8_t>& seeds, bool throughSamples = false);

 private:
  const spirv::Module& m_;
  ValueFlow flow_;
  std::optional<ValueFlow::FlagMap> inputDependent_;
};

}  // namespace stereoshift::analysis
