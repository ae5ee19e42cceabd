// The clip-position analysis: which outputs of a module are its clip position (BuiltIn Position
// variables, the Position member of gl_PerVertex-style blocks, per-vertex arrays of either), the
// pointers that address each of them, and the values that equal the position as the application
// wrote it. clip-position-detection, hud-at-depth, halo and stereo-shift all ask these questions;
// they get one answer from here instead of four hand-written scans that could drift apart.
//
// A pure function of a module: the pass context caches it for the real module (clipPositions() in
// pass.h) and invalidates it when a pass that changed the module does not preserve it; passes that
// look at the folded copy build one for that module directly.
#pragma once

#include "passes/ir/module.h"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace stereoshift {

// Where the clip position lives: an Output variable, or a member of an Output block.
struct ClipPosition {
  uint32_t variable = 0;
  bool isMember = false;
  uint32_t member = 0;        // member index in the block, when isMember
  bool arrayed = false;       // per-vertex arrays (tessellation control, mesh): not shifted here
  std::string description;    // e.g. "gl_PerVertex.gl_Position"

  bool operator==(const ClipPosition&) const = default;
};

class ClipPositionAnalysis {
 public:
  explicit ClipPositionAnalysis(const spirv::Module& module);

  // The clip-position outputs among the entry point's interface, in interface order.
  const std::vector<ClipPosition>& outputs() const { return outputs_; }

  // Pointers to the whole vec4 of output `index`: the variable itself (a plain Position variable),
  // and the access chains that end exactly at it (`block[member]`, or a chain with no index).
  const std::set<uint32_t>& wholePointers(size_t index) const { return whole_[index]; }
  // Access chains into single components of output `index` (`gl_Position.x`, `block[member][i]`).
  const std::set<uint32_t>& componentPointers(size_t index) const { return components_[index]; }
  // Whether `pointer` addresses the whole vec4 of any clip-position output.
  bool addressesWholePosition(uint32_t pointer) const { return allWhole_.count(pointer) > 0; }

  // Values equal to the clip position the application computed, before any shift: every value
  // stored to it, every load of it, and loads of function-local variables whose every store is such
  // a value (a copy kept in a local), to a fixpoint. Only the position's own pointers count, so a
  // value is never here because it was merely derived from the position.
  const std::set<uint32_t>& monoValues() const { return monoValues_; }

  bool operator==(const ClipPositionAnalysis&) const = default;

 private:
  std::vector<ClipPosition> outputs_;
  std::vector<std::set<uint32_t>> whole_, components_;
  std::set<uint32_t> allWhole_;
  std::set<uint32_t> monoValues_;
};

}  // namespace stereoshift
