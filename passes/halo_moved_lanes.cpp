// See halo_moved_lanes.h.
#include "passes/halo_moved_lanes.h"

#include "passes/analysis/clip_positions.h"
#include "passes/deferred_unprojection/linear_form.h"
#include "passes/shift_emitter.h"

#include <algorithm>
#include <map>
#include <set>

namespace stereoshift {

namespace {

using deferred::linear::Decomposer;
using deferred::linear::Lane;
using spirv::Instruction;

// GLSL.std.450 instructions whose result lane is not computed from the same lane of its operands.
bool mixesLanes(uint32_t instruction) {
  switch (instruction) {
    case GLSLstd450Length: case GLSLstd450Distance: case GLSLstd450Cross: case GLSLstd450Normalize:
    case GLSLstd450FaceForward: case GLSLstd450Reflect: case GLSLstd450Refract: case GLSLstd450Determinant:
    case GLSLstd450MatrixInverse: case GLSLstd450PackHalf2x16: case GLSLstd450UnpackHalf2x16:
      return true;
    default:
      return false;
  }
}

// Whether lane `at` of the register copy depends on lane `x` (the position's x), lane by lane where
// the instruction computes lanes apart, every lane of an operand elsewhere; a load of a function
// variable the copy kept, or a chain too deep, counts as depending (it cannot be told).
class LaneDependence {
 public:
  LaneDependence(const analysis::ValueFlow& index, const Decomposer& d, Lane x) : index_(index), d_(d), x_(x) {}

  bool on(Lane at, int depth = 0) {
    at = d_.canonical(at);
    if (at == x_) return true;
    if (depth > 96) return true;
    if (auto it = memo_.find(at); it != memo_.end()) return it->second;
    memo_[at] = false;  // a cycle (a loop's phi) adds nothing of its own
    const bool result = compute(at, depth);
    memo_[at] = result;
    return result;
  }

 private:
  bool compute(Lane at, int depth) {
    const Instruction* def = index_.definition(at.id);
    if (!def) return false;
    auto same = [&](uint32_t id) { return on({id, d_.isVector(id) ? at.lane : 0}, depth + 1); };
    auto every = [&](uint32_t id) {
      if (!index_.definition(id)) return false;  // a type, a literal, a label
      for (uint32_t k = 0; k < d_.lanes(id); ++k)
        if (on({id, k}, depth + 1)) return true;
      return false;
    };
    switch (def->opcode) {
      case spv::OpConstant: case spv::OpConstantComposite: case spv::OpConstantNull: case spv::OpUndef:
      case spv::OpVariable: case spv::OpConstantTrue: case spv::OpConstantFalse:
        return false;
      case spv::OpLoad: {
        const uint32_t root = index_.module().rootVariable(def->operand(0));
        auto storage = root ? index_.module().storageClassOf(root) : std::nullopt;
        return !storage || *storage == spv::StorageClassFunction || *storage == spv::StorageClassPrivate ||
               *storage == spv::StorageClassOutput;
      }
      case spv::OpFAdd: case spv::OpFSub: case spv::OpFMul: case spv::OpFDiv: case spv::OpFNegate:
      case spv::OpFMod: case spv::OpFRem: case spv::OpSelect: case spv::OpConvertFToS: case spv::OpConvertSToF:
      case spv::OpConvertFToU: case spv::OpConvertUToF: case spv::OpBitcast:
        return std::any_of(def->operands.begin(), def->operands.end(), same);
      case spv::OpVectorTimesScalar:
        return same(def->operand(0)) || same(def->operand(1));
      case spv::OpExtInst: {
        if (def->operands.size() < 2) return true;
        const bool mixes = mixesLanes(def->operand(1));
        return std::any_of(def->operands.begin() + 2, def->operands.end(),
                           [&](uint32_t id) { return mixes ? every(id) : same(id); });
      }
      default:
        return std::any_of(def->operands.begin(), def->operands.end(), every);
    }
  }

  const analysis::ValueFlow& index_;
  const Decomposer& d_;
  Lane x_;
  std::map<Lane, bool> memo_;
};

// The lanes of `value` (an output's stored value in the register copy) that move with x, each with
// its coefficient; empty when none does, or when one lane cannot be told exactly.
std::vector<std::pair<uint32_t, float>> movedLanesOf(Decomposer& d, LaneDependence& dependence, uint32_t value, Lane x) {
  std::vector<std::pair<uint32_t, float>> moved;
  for (uint32_t lane = 0; lane < d.lanes(value); ++lane) {
    float coefficient = 0.0f;
    for (const auto& part : d.form({value, lane})) {
      if (!part.term) continue;
      if (*part.term == x) {
        if (part.coefficient.uniform()) return {};  // a cbuffer's coefficient: the text would need its name
        coefficient += part.coefficient.scale;
      } else if (dependence.on(*part.term)) {
        return {};  // x inside a product or a function: not a shift the lane takes linearly
      }
    }
    if (coefficient != 0.0f) moved.push_back({lane, coefficient});
  }
  return moved;
}

// In the module, after the store of `output` (its only one) and the position's store in the same
// block: `output[lane] += coefficient * (shifted x - x)` for each lane, stored again.
bool moveInModule(PassContext& ctx, uint32_t output, const std::vector<std::pair<uint32_t, float>>& lanes) {
  spirv::Module& m = ctx.module;
  const ClipPositionAnalysis& positions = ctx.analyses.clipPositions();
  if (spirv::storesTo(m, output) != 1) return false;
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks) {
      size_t outputAt = block.instructions.size(), positionAt = block.instructions.size();
      for (size_t i = 0; i < block.instructions.size(); ++i) {
        const Instruction& inst = block.instructions[i];
        if (inst.opcode != spv::OpStore) continue;
        if (inst.operand(0) == output) outputAt = i;
        if (positions.addressesWholePosition(inst.operand(0))) positionAt = i;
      }
      if (outputAt == block.instructions.size() || positionAt == block.instructions.size()) continue;
      const uint32_t mono = block.instructions[positionAt].operand(1);
      uint32_t value = block.instructions[outputAt].operand(1);
      const Instruction* valueDef = m.definition(value);
      if (!valueDef) return false;
      const uint32_t type = valueDef->typeId, f32 = m.typeFloat(32);
      const bool vector = type != f32;
      std::vector<Instruction> code;
      const uint32_t shifted = emitShiftedVec4Select(ctx, code, mono);
      auto take = [&](spv::Op op, uint32_t t, std::vector<uint32_t> operands) {
        code.emplace_back(op, t, m.takeId(), std::move(operands));
        return code.back().resultId;
      };
      const uint32_t dx = take(spv::OpFSub, f32, {take(spv::OpCompositeExtract, f32, {shifted, 0}),
                                                   take(spv::OpCompositeExtract, f32, {mono, 0})});
      for (const auto& [lane, coefficient] : lanes) {
        const uint32_t before = vector ? take(spv::OpCompositeExtract, f32, {value, lane}) : value;
        const uint32_t after = take(spv::OpFAdd, f32, {before, take(spv::OpFMul, f32, {dx, m.constantFloat(coefficient)})});
        value = vector ? take(spv::OpCompositeInsert, type, {after, value, lane}) : after;
      }
      code.emplace_back(spv::OpStore, 0, 0, std::vector<uint32_t>{output, value});
      const size_t at = std::max(outputAt, positionAt) + 1;
      block.instructions.insert(block.instructions.begin() + static_cast<long>(at), code.begin(), code.end());
      m.invalidateDefinitions();
      return true;
    }
  return false;
}

// Whether the module writes vector temporaries a lane at a time, over and over, as a decompiler
// writes its registers (`r0.x = ...; r0.yz = ...;`): where a function-local vector takes at least
// `kLaneWrites` stores of single components. Hand-written HLSL keeps its values whole, and the
// module's own flow (halo_pass.cpp) sees through it; the register copy (an optimizer run) is made
// only where it can show what that flow cannot.
constexpr int kLaneWrites = 4;
bool writesRegistersLaneByLane(const spirv::Module& m) {
  int laneWrites = 0;
  spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpStore) return;
    const Instruction* chain = m.definition(inst.operand(0));
    if (!chain || chain->opcode != spv::OpAccessChain || chain->operands.size() != 2) return;
    const uint32_t base = chain->operand(0);
    const Instruction* variable = m.definition(base);
    if (!variable || variable->opcode != spv::OpVariable || m.storageClassOf(base) != spv::StorageClassFunction) return;
    const Instruction* type = m.definition(m.pointeeType(variable->typeId));
    if (type && type->opcode == spv::OpTypeVector) ++laneWrites;
  });
  return laneWrites >= kLaneWrites;
}

}  // namespace

bool moveLanesDerivedFromPositionX(PassContext& ctx, const std::vector<std::string>& fixed) {
  spirv::Module& m = ctx.module;
  HaloFacts& facts = ctx.record.halo;
  facts.movedLanes.clear();
  if (ctx.source.language != SourceLanguage::Hlsl) return false;
  const auto& outputs = ctx.analyses.clipPositions().outputs();
  if (outputs.size() != 1 || outputs.front().isMember) return false;
  // The other float outputs, not built-ins, that the halo pass did not shift already.
  std::set<uint32_t> candidates;
  const uint32_t f32 = m.typeFloat(32);
  for (uint32_t id : m.entryInterface()) {
    if (id == outputs.front().variable || m.hasDecoration(id, spv::DecorationBuiltIn)) continue;
    if (m.storageClassOf(id) != spv::StorageClassOutput) continue;
    const Instruction* type = m.definition(m.pointeeType(m.definition(id)->typeId));
    const bool floats = type && (type->resultId == f32 || (type->opcode == spv::OpTypeVector && type->operand(0) == f32));
    if (floats && std::find(fixed.begin(), fixed.end(), m.name(id)) == fixed.end()) candidates.insert(id);
  }
  if (candidates.empty() || !writesRegistersLaneByLane(m)) return false;
  const spirv::Module* registers = ctx.analyses.registerSsaCopy();
  if (!registers) return false;
  ClipPositionAnalysis registerPositions(*registers);  // global ids are the module's own
  std::vector<uint32_t> positionValues;
  std::map<uint32_t, std::vector<uint32_t>> storedTo;
  spirv::forEachFunctionInstruction(*registers, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpStore) return;
    if (registerPositions.addressesWholePosition(inst.operand(0))) positionValues.push_back(inst.operand(1));
    else if (candidates.count(inst.operand(0))) storedTo[inst.operand(0)].push_back(inst.operand(1));
  });
  if (positionValues.size() != 1) return false;
  analysis::ValueFlow index(*registers);
  Decomposer d(index);
  for (uint32_t lane = 0; lane < 4; ++lane) d.keepWhole({positionValues.front(), lane});
  const Lane x = d.canonical({positionValues.front(), 0});
  LaneDependence dependence(index, d, x);
  bool changed = false;
  for (const auto& [output, values] : storedTo) {
    // Out parameters only (a struct's members, `@entryPointOutput.*`, are for the module's own flow).
    if (values.size() != 1 || m.name(output).empty() || m.name(output).starts_with("@")) continue;
    auto lanes = movedLanesOf(d, dependence, values.front(), x);
    if (lanes.empty() || !moveInModule(ctx, output, lanes)) continue;
    for (const auto& [lane, coefficient] : lanes) facts.movedLanes.push_back({m.name(output), lane, coefficient});
    changed = true;
  }
  return changed;
}

}  // namespace stereoshift
