// Value numbers: which values of a module are equal by what they compute, not by which instruction
// computes them. The halo pass asks it whether an output holds the clip position although the
// shader recomputed the product (`vClip = mvp * p; gl_Position = mvp * p;`), computed it in a
// helper function, wrote it in another but equal way (`vec4(p, 1)` / `vec4(p.x, p.y, p.z, 1)`,
// `p.xyz` of a vec3, `x * 1.0`), or read it back from another output (`gl_Position = outPos`).
//
// Two values get the same number when they are the same pure computation (the same opcode and
// type over operands with the same numbers; commutative operands sorted; vectors compared
// component by component) of the same leaves: constants by value, reads of inputs and uniforms by
// variable and constant access path, reads of a function-local, private or output variable that
// is written exactly once by that one written value, calls of a helper by its returned value with
// the parameters bound to the call's arguments. Anything else (a texel, a loop-carried value,
// memory written twice) is a number of its own, so equal numbers always mean equal values;
// unequal numbers say nothing.
//
// Numbered once, when built: later edits to the module do not change the answers, and ids made
// after it (a pass's clones) have no number.
//
// Linear in the module: every value is numbered once per context (the top level, or one call of a
// helper reached along one chain of calls) and remembered, so shared sub-expressions
// (`a1 = a0 * a0 + a0; a2 = a1 * a1 + a1; ...`) cost one visit each, not two to the power of the
// chain's length; and the whole numbering does at most a fixed multiple of the module's
// instruction count in visits, past which values get numbers of their own (conservative: unequal
// numbers say nothing). HLSL puts the whole entry point in a helper its wrapper calls, so the
// contexts are not a corner case.
#pragma once

#include "passes/ir/module.h"

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

namespace stereoshift::analysis {

class ValueNumbers {
 public:
  explicit ValueNumbers(const spirv::Module& module);

  // The number of a function-body value; nullopt for ids it did not number.
  std::optional<uint32_t> number(uint32_t id) const;
  bool equal(uint32_t a, uint32_t b) const {
    auto na = number(a), nb = number(b);
    return na && nb && *na == *nb;
  }
  // How many values were computed (not looked up): the work the numbering did, for the tests that
  // hold it linear.
  uint64_t visits() const { return visits_; }
  // The most visits one numbering may do: a multiple of the instruction count.
  uint64_t visitBudget() const { return budget_; }

 private:
  using Key = std::vector<uint32_t>;
  // Parameter id -> the number its argument has at the call being looked through; for a pointer
  // parameter, the number of the value the argument's variable holds.
  using Bindings = std::map<uint32_t, uint32_t>;

  // A context: 0 is the top level; every other one is one call instruction reached from a parent
  // context, with the bindings of that call.
  using Context = uint32_t;

  uint32_t numberOf(uint32_t id, Context context, int depth);
  uint32_t compute(uint32_t id, Context context, int depth);
  uint32_t component(uint32_t vector, uint32_t index, Context context, int depth);
  std::optional<uint32_t> memoryValue(uint32_t pointer, Context context, int depth);
  std::optional<Context> callContext(const spirv::Instruction& call, Context parent, int depth);
  uint32_t intern(Key key);
  uint32_t fresh();

  const spirv::Module& m_;
  std::map<Key, uint32_t> interned_;
  // Numbers by (context << 32 | id), the top level's under the id itself: inside a helper the same
  // id means other values at other calls, so each call's numbers are kept apart.
  std::unordered_map<uint64_t, uint32_t> numbers_;
  std::deque<Bindings> contexts_;                        // by Context; a deque keeps references valid
  std::map<std::pair<Context, uint32_t>, Context> callContexts_;  // (parent, call id) -> context
  uint64_t visits_ = 0;
  uint64_t budget_ = 0;
  std::unordered_map<uint32_t, std::vector<const spirv::Instruction*>> storesTo_;  // root -> stores
  std::unordered_map<uint32_t, const spirv::Function*> functions_;
  std::unordered_map<uint32_t, std::vector<uint32_t>> returns_;
  uint32_t next_ = 1;
};

}  // namespace stereoshift::analysis
