// Value flow: the one data-flow analysis the passes share, for "where does this value go" and
// "what is this value computed from" on one module.
//
// A ValueFlow indexes the module once: def-use lists, memory (every store and memory copy by the
// variable or pointer parameter it writes, with the constant access path into it; every load by
// the variable it reads), and calls (call sites, returned values, parameter positions, pointer
// arguments). Two engines run on that index, each a thin loop whose pass-specific questions are
// rules the pass supplies:
//
//   - forward: propagate(seeds, rules) follows flags from seed values (or variables) to every
//     value computed from them, through arithmetic, phis and function-local memory (a store of a
//     flagged value into a variable flags the variable, its loads carry the flags on), to a fixed
//     point. per-eye-view asks it which values a camera subtraction becomes and where they go, and
//     which values vary per vertex or pixel.
//   - backward: BackwardFlow<Facts, Rules>::value(id, path) works out what a value, or one element
//     of it by access path, is computed from: through composites component by component, phis,
//     selects, arithmetic, every store that may reach a load (whatever the control flow: an
//     over-approximation), helper functions (value and pointer parameters followed to every call
//     site, results to every return). deferred-unprojection asks it what each component of a
//     matrix product's vector is made of.
//
// The index points into the module's instruction vectors: build a ValueFlow on a module that does
// not change while it is in use (the folded copy, a pass's detection phase before it edits), and a
// new one after an edit.
#pragma once

#include "passes/ir/def_use.h"
#include "passes/ir/module.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace stereoshift::analysis {

// An index of an access chain that is not a compile-time constant: it may address any element.
constexpr uint32_t kAnyIndex = 0xFFFFFFFFu;
// Constant member / element indices from a variable (or a value) down to a part of it.
using AccessPath = std::vector<uint32_t>;

// Whether `prefix` addresses `full` or a whole that contains it (kAnyIndex matches any index).
bool pathPrefixOf(const AccessPath& prefix, const AccessPath& full);

// What a pointer addresses: its root (an OpVariable or a pointer OpFunctionParameter) and the
// access path into the root.
struct PointerTarget {
  uint32_t root = 0;
  AccessPath path;
};

class ValueFlow {
 public:
  explicit ValueFlow(const spirv::Module& module);
  ValueFlow(const ValueFlow&) = delete;
  ValueFlow& operator=(const ValueFlow&) = delete;

  const spirv::Module& module() const { return module_; }
  const spirv::DefUse& defUse() const { return defUse_; }
  const spirv::Instruction* definition(uint32_t id) const { return defUse_.definition(id); }

  // ---- memory ----
  // The root and access path of a pointer, through access chains and copies; nullopt when it
  // comes from anything else (a load of a pointer, a select between pointers, ...).
  std::optional<PointerTarget> resolvePointer(uint32_t pointer) const;

  struct Write {
    const spirv::Instruction* instruction = nullptr;  // OpStore or OpCopyMemory
    AccessPath path;                                   // where in the root it writes
  };
  // Every store and memory copy into `root`, in module order.
  const std::vector<Write>& writesTo(uint32_t root) const;
  // Every OpLoad whose pointer resolves to `root`, in module order.
  const std::vector<const spirv::Instruction*>& loadsFrom(uint32_t root) const;

  // ---- calls ----
  struct ParameterPosition {
    uint32_t function = 0;
    size_t index = 0;
  };
  const std::vector<const spirv::Instruction*>& callsTo(uint32_t function) const;
  // The values a function returns (OpReturnValue operands).
  const std::vector<uint32_t>& returnsOf(uint32_t function) const;
  // The function and position of a parameter id; nullopt for anything else.
  std::optional<ParameterPosition> parameterOf(uint32_t id) const;
  // The (callee, parameter) pairs that receive a pointer into `root` as an argument.
  const std::vector<ParameterPosition>& pointerArgumentsOf(uint32_t root) const;

  // ---- forward engine ----
  using Flags = uint32_t;
  using FlagMap = std::unordered_map<uint32_t, Flags>;

  static Flags flagsOf(const FlagMap& flags, uint32_t id) {
    auto it = flags.find(id);
    return it == flags.end() ? 0 : it->second;
  }
  // The union of the flags of an instruction's value operands; *flaggedOperands (if given) counts
  // the operands that carry any.
  static Flags operandFlags(const spirv::Instruction& inst, const FlagMap& flags, int* flaggedOperands = nullptr);

  // What a pass decides while flags propagate. The engine handles loads itself (a load takes the
  // flags of the variable it reads) and asks the rules about everything else. Rules must be
  // monotone (more flags in, never fewer out) and may read the flags of any id: the engine runs to
  // the least fixed point whatever they read.
  class ForwardRules {
   public:
    virtual ~ForwardRules() = default;
    // A store writes a value with `flags` into memory rooted at `root`: true when loads of the
    // root carry the flags on (a local), false when the value leaves the analysis here (an
    // output, which a rule may note as a sink).
    virtual bool storeCarries(const spirv::Instruction& store, uint32_t root, Flags flags) = 0;
    // The flags of `inst`'s result (any function-body instruction with a result id but OpLoad).
    virtual Flags resultFlags(const spirv::Instruction& inst, const FlagMap& flags) = 0;
  };

  // Flags of every value (and every variable written with a flagged value) reachable from the
  // seeds, seeds included; ids without flags are absent.
  FlagMap propagate(const FlagMap& seeds, ForwardRules& rules) const;

 private:
  const spirv::Module& module_;
  spirv::DefUse defUse_;
  std::unordered_map<uint32_t, std::vector<Write>> writesTo_;
  std::unordered_map<uint32_t, std::vector<const spirv::Instruction*>> loadsFrom_;
  std::unordered_map<uint32_t, std::vector<const spirv::Instruction*>> callsTo_;
  std::unordered_map<uint32_t, std::vector<uint32_t>> returnsOf_;
  std::unordered_map<uint32_t, ParameterPosition> parameterOf_;
  std::unordered_map<uint32_t, std::vector<ParameterPosition>> pointerArguments_;
};

// ---- backward engine ----------------------------------------------------------------------------
//
// Facts: what a value is computed from, as the pass wants to know it. Default-constructed it
// means "computed from nothing"; `facts |= other` joins two answers.
// Rules: the pass's leaves and labels, with these members:
//   std::optional<Facts> leaf(const Instruction& def, const AccessPath& path)
//       answers for `def` before the engine looks at it (constants, texel reads, values the pass
//       treats as opaque); nullopt lets the engine go on;
//   Facts unknown()
//       the answer for what the engine cannot see through (undefined values, unknown opcodes,
//       pointers it cannot resolve, a spent step budget);
//   Facts moduleVariable(const Instruction& variable, const AccessPath& path)
//       a load from a variable that is not memory the shader writes itself (inputs, uniforms,
//       storage): Function, Private and Output variables are followed through their stores;
//   void computed(const Instruction& def, Facts& facts)
//       called after the engine joined the operands of an instruction that computes a new value
//       (arithmetic, comparisons, derivatives, ext-insts, matrix and vector products), so the
//       pass can mark the answer as "computed, not only moved".
// Answers are memoised per (id, path); a cycle (a loop through a phi or a local) is cut and the
// answers that depended on the cut are not memoised, so asking in another order gives the same.
template <class Facts, class Rules>
class BackwardFlow {
 public:
  BackwardFlow(const ValueFlow& index, Rules& rules) : index_(index), rules_(rules) {}

  Facts value(uint32_t id, AccessPath path = {}) { return trace(id, std::move(path)).facts; }

 private:
  using Instruction = spirv::Instruction;
  static constexpr int kStepBudget = 200000;

  struct Traced {
    Facts facts{};
    bool cycleCut = false;  // part of the answer was cut at a cycle: not memoised
    Traced& operator|=(const Traced& o) {
      facts |= o.facts;
      cycleCut |= o.cycleCut;
      return *this;
    }
  };

  const ValueFlow& index_;
  Rules& rules_;
  std::map<std::pair<uint32_t, AccessPath>, Facts> cache_;
  std::set<std::pair<uint32_t, AccessPath>> visiting_;
  int steps_ = 0;

  Traced unknown() { return Traced{rules_.unknown(), false}; }
  static AccessPath rest(const AccessPath& path) { return AccessPath(path.begin() + 1, path.end()); }

  uint32_t vectorSize(uint32_t id) const {
    const Instruction* def = index_.definition(id);
    const Instruction* type = def ? index_.definition(def->typeId) : nullptr;
    return type && type->opcode == spv::OpTypeVector ? type->operand(1) : 0;
  }
  bool isVector(uint32_t id) const { return vectorSize(id) != 0; }
  uint32_t componentCount(uint32_t id) const { return std::max(vectorSize(id), 1u); }

  Traced trace(uint32_t id, AccessPath path) {
    // A dynamic index selects any element: the whole value answers for it.
    if (auto any = std::find(path.begin(), path.end(), kAnyIndex); any != path.end()) path.erase(any, path.end());
    auto key = std::make_pair(id, path);
    if (auto it = cache_.find(key); it != cache_.end()) return Traced{it->second, false};
    if (visiting_.count(key)) return Traced{Facts{}, true};
    if (++steps_ > kStepBudget) return unknown();
    visiting_.insert(key);
    Traced result = compute(id, path);
    visiting_.erase(key);
    if (!result.cycleCut) cache_[key] = result.facts;
    if (visiting_.empty()) result.cycleCut = false;
    return result;
  }

  // Joins the operands of `def`, each with `path` where it is a vector (a component-by-component
  // operation keeps the component) and whole otherwise.
  Traced joinOperands(const Instruction& def, size_t first, const AccessPath& path, bool componentwise) {
    Traced s;
    for (size_t k = first; k < def.operands.size(); ++k) {
      uint32_t operand = def.operands[k];
      s |= trace(operand, componentwise && isVector(operand) ? path : AccessPath{});
    }
    return s;
  }

  Traced computed(const Instruction& def, Traced s) {
    rules_.computed(def, s.facts);
    return s;
  }

  Traced compute(uint32_t id, const AccessPath& path) {
    const Instruction* def = index_.definition(id);
    if (!def) return unknown();
    if (auto leaf = rules_.leaf(*def, path)) return Traced{*leaf, false};
    Traced s;
    switch (def->opcode) {
      case spv::OpConstantComposite:
        if (!path.empty() && path[0] < def->operands.size()) return trace(def->operands[path[0]], rest(path));
        for (uint32_t element : def->operands) s |= trace(element, {});
        return s;
      case spv::OpCopyObject:
        return trace(def->operand(0), path);
      case spv::OpLoad: {
        auto target = index_.resolvePointer(def->operand(0));
        if (!target) return unknown();
        target->path.insert(target->path.end(), path.begin(), path.end());
        return load(target->root, target->path);
      }
      case spv::OpCompositeExtract: {
        AccessPath inner(def->operands.begin() + 1, def->operands.end());
        inner.insert(inner.end(), path.begin(), path.end());
        return trace(def->operand(0), inner);
      }
      case spv::OpCompositeConstruct: {
        const Instruction* type = index_.definition(def->typeId);
        bool vector = type && type->opcode == spv::OpTypeVector;
        if (path.empty()) {
          for (uint32_t part : def->operands) s |= trace(part, {});
          return s;
        }
        if (!vector) return path[0] < def->operands.size() ? trace(def->operands[path[0]], rest(path)) : unknown();
        uint32_t first = 0;  // vector constituents are flattened: find the one holding the component
        for (uint32_t part : def->operands) {
          uint32_t count = componentCount(part);
          if (path[0] < first + count) return trace(part, isVector(part) ? AccessPath{path[0] - first} : AccessPath{});
          first += count;
        }
        return unknown();
      }
      case spv::OpCompositeInsert: {
        AccessPath at(def->operands.begin() + 2, def->operands.end());
        if (pathPrefixOf(at, path))
          return trace(def->operand(0), AccessPath(path.begin() + static_cast<long>(at.size()), path.end()));
        if (pathPrefixOf(path, at)) {
          s |= trace(def->operand(0), {});
          s |= trace(def->operand(1), path);
          return s;
        }
        return trace(def->operand(1), path);
      }
      case spv::OpVectorShuffle: {
        uint32_t firstCount = componentCount(def->operand(0));
        auto pick = [&](uint32_t component) {
          if (component == 0xFFFFFFFFu) return Traced{};  // undefined lane
          return component < firstCount ? trace(def->operand(0), {component})
                                        : trace(def->operand(1), {component - firstCount});
        };
        if (!path.empty()) return 2 + path[0] < def->operands.size() ? pick(def->operands[2 + path[0]]) : unknown();
        for (size_t k = 2; k < def->operands.size(); ++k) s |= pick(def->operands[k]);
        return s;
      }
      case spv::OpPhi:
        for (size_t k = 0; k < def->operands.size(); k += 2) s |= trace(def->operands[k], path);
        return s;
      case spv::OpSelect:
        return joinOperands(*def, 0, path, true);
      case spv::OpFAdd: case spv::OpFSub: case spv::OpFMul: case spv::OpFDiv: case spv::OpFMod:
      case spv::OpFRem: case spv::OpFNegate: case spv::OpIAdd: case spv::OpISub: case spv::OpIMul:
      case spv::OpSNegate: case spv::OpConvertFToS: case spv::OpConvertFToU: case spv::OpConvertSToF:
      case spv::OpConvertUToF: case spv::OpFConvert: case spv::OpBitcast: case spv::OpVectorTimesScalar:
      case spv::OpSDiv: case spv::OpUDiv: case spv::OpSMod: case spv::OpUMod: case spv::OpSRem:
      case spv::OpBitwiseAnd: case spv::OpBitwiseOr: case spv::OpBitwiseXor: case spv::OpNot:
      case spv::OpShiftLeftLogical: case spv::OpShiftRightLogical: case spv::OpShiftRightArithmetic:
      case spv::OpFOrdEqual: case spv::OpFOrdNotEqual: case spv::OpFOrdLessThan: case spv::OpFOrdGreaterThan:
      case spv::OpFOrdLessThanEqual: case spv::OpFOrdGreaterThanEqual: case spv::OpFUnordEqual:
      case spv::OpFUnordNotEqual: case spv::OpFUnordLessThan: case spv::OpFUnordGreaterThan:
      case spv::OpFUnordLessThanEqual: case spv::OpFUnordGreaterThanEqual: case spv::OpIEqual:
      case spv::OpINotEqual: case spv::OpSLessThan: case spv::OpSGreaterThan: case spv::OpSLessThanEqual:
      case spv::OpSGreaterThanEqual: case spv::OpULessThan: case spv::OpUGreaterThan:
      case spv::OpULessThanEqual: case spv::OpUGreaterThanEqual: case spv::OpLogicalAnd: case spv::OpLogicalOr:
      case spv::OpLogicalNot: case spv::OpLogicalEqual: case spv::OpLogicalNotEqual: case spv::OpIsNan:
      case spv::OpIsInf: case spv::OpDPdx: case spv::OpDPdy: case spv::OpFwidth: case spv::OpDPdxFine:
      case spv::OpDPdyFine: case spv::OpFwidthFine: case spv::OpDPdxCoarse: case spv::OpDPdyCoarse:
      case spv::OpFwidthCoarse:
        return computed(*def, joinOperands(*def, 0, path, true));
      case spv::OpExtInst:
        return computed(*def, joinOperands(*def, 2, path, isComponentwiseExtInst(*def)));
      case spv::OpMatrixTimesVector: case spv::OpVectorTimesMatrix: case spv::OpMatrixTimesMatrix:
      case spv::OpMatrixTimesScalar: case spv::OpDot: case spv::OpTranspose: case spv::OpOuterProduct:
      case spv::OpAny: case spv::OpAll: case spv::OpVectorExtractDynamic: case spv::OpVectorInsertDynamic:
        return computed(*def, joinOperands(*def, 0, path, false));
      case spv::OpFunctionParameter: {  // a value parameter: whatever each call passes
        auto position = index_.parameterOf(id);
        const auto& calls = index_.callsTo(position ? position->function : 0);
        for (const Instruction* call : calls) s |= trace(call->operand(1 + position->index), path);
        if (calls.empty()) s |= unknown();
        return s;
      }
      case spv::OpFunctionCall: {
        const auto& returned = index_.returnsOf(def->operand(0));
        for (uint32_t value : returned) s |= trace(value, path);
        if (returned.empty()) s |= unknown();
        return s;
      }
      default:
        return unknown();  // OpUndef, depth comparisons, queries, atomics, ...
    }
  }

  // GLSL.std.450 instructions work component by component on vectors, except these.
  bool isComponentwiseExtInst(const Instruction& def) const;

  Traced load(uint32_t root, const AccessPath& path) {
    const Instruction* def = index_.definition(root);
    if (!def) return unknown();
    Traced s;
    if (def->opcode == spv::OpVariable) {
      switch (static_cast<spv::StorageClass>(def->operand(0))) {
        case spv::StorageClassFunction: case spv::StorageClassPrivate: case spv::StorageClassOutput:
          if (def->operands.size() > 1) s |= trace(def->operand(1), path);  // initializer
          s |= stores(root, path);
          return s;
        default:
          return Traced{rules_.moduleVariable(*def, path), false};
      }
    }
    if (def->opcode == spv::OpFunctionParameter) {  // a pointer parameter: the caller's memory
      s |= stores(root, path);
      auto position = index_.parameterOf(root);
      for (const Instruction* call : index_.callsTo(position ? position->function : 0)) {
        auto argument = index_.resolvePointer(call->operand(1 + position->index));
        if (!argument) {
          s |= unknown();
          continue;
        }
        argument->path.insert(argument->path.end(), path.begin(), path.end());
        s |= load(argument->root, argument->path);
      }
      return s;
    }
    return unknown();
  }

  // Every write that may reach a load of (root, path): stores to it, to a part of it or to a whole
  // that contains it; memory copies and writes by a callee through a pointer argument are opaque.
  Traced stores(uint32_t root, const AccessPath& path) {
    Traced s;
    for (const auto& write : index_.writesTo(root)) {
      if (write.instruction->opcode == spv::OpCopyMemory) {
        if (pathPrefixOf(write.path, path) || pathPrefixOf(path, write.path)) s |= unknown();
        continue;
      }
      if (pathPrefixOf(write.path, path))
        s |= trace(write.instruction->operand(1),
                   AccessPath(path.begin() + static_cast<long>(write.path.size()), path.end()));
      else if (pathPrefixOf(path, write.path))
        s |= trace(write.instruction->operand(1), {});
    }
    for (const auto& [function, index] : index_.pointerArgumentsOf(root)) {
      const spirv::Function* callee = index_.module().function(function);
      if (callee && index < callee->parameters.size() && !index_.writesTo(callee->parameters[index].resultId).empty())
        s |= unknown();
    }
    return s;
  }
};

// Shared by every BackwardFlow instantiation (defined in value_flow.cpp).
bool isComponentwiseGlslInstruction(uint32_t glslInstruction);

template <class Facts, class Rules>
bool BackwardFlow<Facts, Rules>::isComponentwiseExtInst(const Instruction& def) const {
  return isComponentwiseGlslInstruction(def.operand(1));
}

}  // namespace stereoshift::analysis
