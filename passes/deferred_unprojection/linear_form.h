// The linear forms the decompiled-HLSL recognisers (row_products.cpp) read a register copy with: a
// lane of a value as a sum of terms, each with one uniform element (or a constant) as its
// coefficient, found through moves, sums, negations, `mad`/fma, dot products and products with a
// uniform element or a constant; anything else is an opaque term. With it, the OpLine of each
// value and the names the source gives uniform elements ("cb1[20].x", "InvViewProj[2].x").
#pragma once

#include "passes/analysis/uniform_slots.h"
#include "passes/deferred_unprojection/sources.h"
#include "passes/ir/walker.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stereoshift::deferred::linear {

using analysis::kAnyIndex;
using spirv::Instruction;

// scale * (a uniform element, or 1 when `root` is 0).
struct Coefficient {
  uint32_t root = 0;
  AccessPath path;
  float scale = 1.0f;
  bool uniform() const { return root != 0; }
};

// One lane of a value: an SSA id and the vector lane (0 for a scalar).
struct Lane {
  uint32_t id = 0;
  uint32_t lane = 0;
  auto operator<=>(const Lane&) const = default;
};

// A scalar as a sum of coefficient * term (a term-less part is a constant or uniform addend).
struct Part {
  std::optional<Lane> term;
  Coefficient coefficient;
};
using Linear = std::vector<Part>;

class Decomposer {
 public:
  explicit Decomposer(const ValueFlow& index) : index_(index), m_(index.module()) {}

  // Follows moves (extracts, inserts, shuffles, constructs, copies) to the lane of the value that
  // computes it.
  Lane canonical(Lane at) const {
    for (int step = 0; step < 64; ++step) {
      const Instruction* def = index_.definition(at.id);
      if (!def) return at;
      switch (def->opcode) {
        case spv::OpCopyObject: at.id = def->operand(0); continue;
        case spv::OpCompositeExtract:
          if (def->operands.size() != 2 || !isVector(def->operand(0))) return at;
          at = {def->operand(0), def->operand(1)};
          continue;
        case spv::OpCompositeInsert:
          if (def->operands.size() != 3 || !isVector(def->resultId)) return at;
          at = def->operand(2) == at.lane ? Lane{def->operand(0), 0} : Lane{def->operand(1), at.lane};
          continue;
        case spv::OpVectorShuffle: {
          uint32_t pick = def->operand(2 + at.lane), first = lanes(def->operand(0));
          if (pick == 0xFFFFFFFFu || 2 + at.lane >= def->operands.size()) return at;
          at = pick < first ? Lane{def->operand(0), pick} : Lane{def->operand(1), pick - first};
          continue;
        }
        case spv::OpCompositeConstruct: {
          if (!isVector(def->resultId)) return at;
          uint32_t first = 0;
          bool found = false;
          for (uint32_t part : def->operands) {
            uint32_t count = isVector(part) ? lanes(part) : 1;
            if (at.lane < first + count) {
              at = {part, isVector(part) ? at.lane - first : 0};
              found = true;
              break;
            }
            first += count;
          }
          if (!found) return at;
          continue;
        }
        default: return at;
      }
    }
    return at;
  }

  // A lane to take as a term of its own, not decomposed further (the halo pass's position lanes:
  // what an output adds of them, not of what they are computed from). Before any form().
  void keepWhole(Lane at) { whole_.insert(canonical(at)); }

  // The linear form of one lane, memoised; nullopt never (an opaque value is a term of its own).
  const Linear& form(Lane at) {
    at = canonical(at);
    if (auto it = memo_.find(at); it != memo_.end()) return it->second;
    Linear value = compute(at);
    return memo_.emplace(at, std::move(value)).first->second;
  }

  // The uniform element (with a constant scale) a lane is, if it is one.
  std::optional<Coefficient> uniformElement(Lane at) {
    const Linear& f = form(at);
    if (f.size() != 1 || f[0].term || !f[0].coefficient.uniform()) return std::nullopt;
    return f[0].coefficient;
  }
  // The constant a lane is, if it is one (0 for a zero).
  std::optional<float> constant(Lane at) {
    const Linear& f = form(at);
    if (f.empty()) return 0.0f;
    if (f.size() != 1 || f[0].term || f[0].coefficient.uniform()) return std::nullopt;
    return f[0].coefficient.scale;
  }
  const Instruction* definition(uint32_t id) const { return index_.definition(id); }

  bool isVector(uint32_t id) const { return lanes(id) > 1; }
  uint32_t lanes(uint32_t id) const {
    const Instruction* def = index_.definition(id);
    const Instruction* type = def ? m_.definition(def->typeId) : nullptr;
    return type && type->opcode == spv::OpTypeVector ? type->operand(1) : 1;
  }

 private:
  const ValueFlow& index_;
  const spirv::Module& m_;
  std::map<Lane, Linear> memo_;
  std::set<Lane> whole_;
  int depth_ = 0;
  size_t computed_ = 0;

 public:
  // Lanes decomposed and parts built for them: the work, for the complexity tests.
  size_t computed() const { return computed_; }

 private:

  static std::optional<Coefficient> pure(const Linear& f) {
    if (f.size() != 1 || f[0].term) return std::nullopt;
    return f[0].coefficient;
  }
  static Linear scaled(Linear f, float by) {
    for (auto& p : f) p.coefficient.scale *= by;
    return f;
  }
  static Linear sum(Linear a, const Linear& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }
  Linear opaque(Lane at) const { return {Part{canonical(at), {}}}; }
  Lane laneOf(uint32_t id, uint32_t lane) const { return {id, isVector(id) ? lane : 0}; }

  // a * b: a constant scales the other side; a uniform element is the coefficient of the other
  // side taken whole (an opaque term); anything else is opaque as a whole (`self`).
  Linear product(Lane a, Lane b, Lane self) {
    const Linear fa = form(a), fb = form(b);
    if (fa.empty() || fb.empty()) return {};  // a zero
    auto ca = pure(fa), cb = pure(fb);
    if (ca && cb) {
      if (ca->uniform() && cb->uniform()) return opaque(self);
      Coefficient c = ca->uniform() ? *ca : *cb;
      c.scale = ca->scale * cb->scale;
      return {Part{std::nullopt, c}};
    }
    if (cb) return cb->uniform() ? Linear{Part{canonical(a), *cb}} : scaled(fa, cb->scale);
    if (ca) return ca->uniform() ? Linear{Part{canonical(b), *ca}} : scaled(fb, ca->scale);
    return opaque(self);
  }

  Linear uniformLoad(const Instruction& load, Lane at) const {
    auto target = index_.resolvePointer(load.operand(0));
    auto storage = target ? m_.storageClassOf(target->root) : std::nullopt;
    bool uniform = storage && (*storage == spv::StorageClassUniform || *storage == spv::StorageClassPushConstant);
    if (!uniform || std::count(target->path.begin(), target->path.end(), kAnyIndex)) return opaque(at);
    Coefficient c{target->root, target->path, 1.0f};
    if (isVector(load.resultId)) c.path.push_back(at.lane);
    return {Part{std::nullopt, c}};
  }

  // A component of a matrix product has four parts; a longer sum is opaque (and a sum of a value
  // with itself, `a1 = a0 + a0` chained, cannot double its parts at every step).
  static constexpr size_t kMaxParts = 8;

  Linear compute(Lane at) {
    if (whole_.count(at)) return opaque(at);
    const Instruction* def = index_.definition(at.id);
    if (!def || ++depth_ > 256) {
      --depth_;
      return opaque(at);
    }
    Linear out = computeFor(*def, at);
    --depth_;
    computed_ += 1 + out.size();  // the lane and the parts built for it
    if (out.size() > kMaxParts) return opaque(at);
    return out;
  }

  Linear computeFor(const Instruction& def, Lane at) {
    auto op = [&](size_t k) { return laneOf(def.operand(k), at.lane); };
    switch (def.opcode) {
      case spv::OpConstant: {
        auto value = m_.floatConstant(def.resultId);
        if (!value) return opaque(at);
        if (*value == 0.0f) return {};
        return {Part{std::nullopt, Coefficient{0, {}, *value}}};
      }
      case spv::OpConstantComposite:
        return at.lane < def.operands.size() ? form({def.operands[at.lane], 0}) : opaque(at);
      case spv::OpConstantNull: return {};
      case spv::OpLoad: return uniformLoad(def, at);
      case spv::OpFAdd: return sum(form(op(0)), form(op(1)));
      case spv::OpFSub: return sum(form(op(0)), scaled(form(op(1)), -1.0f));
      case spv::OpFNegate: return scaled(form(op(0)), -1.0f);
      case spv::OpFMul: return product(op(0), op(1), at);
      case spv::OpVectorTimesScalar: return product({def.operand(0), at.lane}, {def.operand(1), 0}, at);
      case spv::OpDot: {
        Linear out;
        for (uint32_t k = 0; k < lanes(def.operand(0)); ++k)
          out = sum(std::move(out), product({def.operand(0), k}, {def.operand(1), k}, at));
        return out;
      }
      case spv::OpExtInst:
        if (def.operand(1) == GLSLstd450Fma && def.operands.size() == 5)
          return sum(product(laneOf(def.operand(2), at.lane), laneOf(def.operand(3), at.lane), at),
                     form(laneOf(def.operand(4), at.lane)));
        return opaque(at);
      default: return opaque(at);
    }
  }
};

// The OpLine line of an instruction, when it is in the main file (glslang names each OpLine's file
// as the front end named the text it parsed: the input's path, an #include's resolved name).
class LineMap {
 public:
  LineMap(const spirv::Module& m, const std::string& mainFile) {
    for (const auto& inst : m.debugSource)
      if (inst.opcode == spv::OpString && inst.stringOperand(0) == mainFile) mainFile_ = inst.resultId;
    for (const auto& fn : m.functions)
      for (const auto& block : fn.blocks) {
        uint32_t line = 0;
        for (const auto& inst : block.instructions) {
          if (inst.opcode == spv::OpLine) line = inst.operand(0) == mainFile_ ? inst.operand(1) : 0;
          else if (inst.opcode == spv::OpNoLine) line = 0;
          else if (inst.resultId) lines_[inst.resultId] = line;
        }
      }
  }
  bool present() const { return mainFile_ != 0; }
  uint32_t lineOf(uint32_t id) const {
    auto it = lines_.find(id);
    return it == lines_.end() ? 0 : it->second;
  }

 private:
  uint32_t mainFile_ = 0;
  std::map<uint32_t, uint32_t> lines_;
};

// What one lane of a value is computed from (a vector's lane, a scalar whole).
inline Sources sourcesOf(SourceAnalysis& flow, const Decomposer& d, Lane at) {
  return flow.value(at.id, d.isVector(at.id) ? AccessPath{at.lane} : AccessPath{});
}

// A uniform element as the source names it: "cb1[20].x" (an HLSL cbuffer's members are global
// names), with the coefficient's sign or scale.
inline std::string elementText(const spirv::Module& m, const Coefficient& c) {
  if (c.path.empty()) return "";
  std::string text = describe(m, c.root, {c.path[0]});
  const Instruction* var = m.definition(c.root);
  uint32_t type = var ? m.pointeeType(var->typeId) : 0;
  for (size_t k = 0; k < c.path.size(); ++k) {
    const Instruction* t = m.definition(type);
    if (!t) return "";
    if (t->opcode == spv::OpTypeStruct) {
      if (k != 0) return "";  // a member of a nested struct: not a decompiler's cbuffer
      type = t->operand(c.path[k]);
    } else if (t->opcode == spv::OpTypeArray || t->opcode == spv::OpTypeMatrix) {
      text += "[" + std::to_string(c.path[k]) + "]";
      type = t->operand(0);
    } else if (t->opcode == spv::OpTypeVector && c.path[k] < 4) {
      text += std::string(".") + "xyzw"[c.path[k]];
      type = t->operand(0);
    } else {
      return "";
    }
  }
  if (c.scale == 1.0f) return text;
  if (c.scale == -1.0f) return "-" + text;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(c.scale));
  return "(" + std::string(buf) + " * " + text + ")";
}

inline bool isFloat4(const spirv::Module& m, uint32_t type) {
  const Instruction* vector = m.definition(type);
  if (!vector || vector->opcode != spv::OpTypeVector || vector->operand(1) != 4) return false;
  const Instruction* component = m.definition(vector->operand(0));
  return component && component->opcode == spv::OpTypeFloat && component->operand(0) == 32;
}

}  // namespace stereoshift::deferred::linear
