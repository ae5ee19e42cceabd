// halo: turns outputs computed from the clip position before the shift (a copied position, screen
// UVs derived from it) into ones computed from the shifted position, so they move with the geometry
// instead of leaving a mono "halo" behind (a known 3Dmigoto artifact).
//
// Data flow tracked (the clip-position analysis's mono values): values stored to the position,
// loads of the position, and function-local variables whose every store is such a value. Each other output whose stored value is computed
// from one of those, through pure arithmetic in the same function, gets that computation cloned
// with the position replaced by its shifted value (the same instruction sequence as the shift).
//
// "One of those" is decided by value, not by instruction (analysis/value_numbers.h): a product
// recomputed for the output (`vClip = mvp * p; gl_Position = mvp * p;`), the same product in a
// helper function or written another equal way is the position too. The reverse, the position read
// back from an output (`outPos = P * V * M * p; gl_Position = outPos;`), shifts the output and has
// the position read the mono value it was computed from, so stereo-shift shifts it once.
//
// Decompiled HLSL's outputs computed through registers lane by lane: halo_moved_lanes.h.
#include "passes/pass.h"
#include "passes/halo_moved_lanes.h"
#include "passes/pass_registry.h"
#include "passes/shift_emitter.h"

#include "passes/analysis/uniform_slots.h"
#include "passes/analysis/value_numbers.h"
#include "passes/ir/walker.h"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace stereoshift {

using spirv::Instruction;

namespace {

bool isPureArithmetic(spv::Op op) {
  switch (op) {
    case spv::OpCompositeExtract: case spv::OpCompositeConstruct: case spv::OpCompositeInsert:
    case spv::OpVectorShuffle: case spv::OpFAdd: case spv::OpFSub: case spv::OpFMul: case spv::OpFDiv:
    case spv::OpFNegate: case spv::OpVectorTimesScalar: case spv::OpMatrixTimesVector:
    case spv::OpVectorTimesMatrix: case spv::OpDot: case spv::OpExtInst: case spv::OpCopyObject:
    case spv::OpFMod: case spv::OpSelect:
      return true;
    default:
      return false;
  }
}

// The operands of a pure-arithmetic instruction that are values (ids): all but the literal indices
// of extracts, inserts and shuffles and an ext-inst's set and number, as [first, last).
std::pair<size_t, size_t> valueOperands(const Instruction& inst) {
  size_t last = inst.operands.size();
  if (inst.opcode == spv::OpCompositeExtract) last = 1;
  if (inst.opcode == spv::OpCompositeInsert || inst.opcode == spv::OpVectorShuffle) last = 2;
  return {inst.opcode == spv::OpExtInst ? 2 : 0, std::min(last, inst.operands.size())};
}

// The source spelling of the output part `pointer` addresses (`vClip`, `surf.clip`, `copies[1]`):
// its variable's name and, through constant access-chain indices, struct member names and array
// indices. Empty for a vector component, a variable index or a missing name.
std::string outputPath(const spirv::Module& m, uint32_t pointer) {
  std::vector<const Instruction*> chain;
  for (int depth = 0;; ++depth) {
    const Instruction* def = m.definition(pointer);
    if (!def || depth > 16) return {};
    if (def->opcode == spv::OpVariable) break;
    if (def->opcode != spv::OpAccessChain && def->opcode != spv::OpInBoundsAccessChain) return {};
    chain.push_back(def);
    pointer = def->operand(0);
  }
  std::string path = m.name(pointer);
  const Instruction* pointerType = m.definition(m.definition(pointer)->typeId);
  if (path.empty() || !pointerType || pointerType->opcode != spv::OpTypePointer) return {};
  uint32_t type = pointerType->operand(1);
  for (auto link = chain.rbegin(); link != chain.rend(); ++link)
    for (size_t k = 1; k < (*link)->operands.size(); ++k) {
      const Instruction* index = m.definition((*link)->operand(k));
      const Instruction* composite = m.definition(type);
      if (!index || index->opcode != spv::OpConstant || !composite) return {};
      const uint32_t at = index->operand(0);
      if (composite->opcode == spv::OpTypeStruct && at < composite->operands.size()) {
        std::string member = m.memberName(type, at);
        if (member.empty()) return {};
        path += "." + member;
        type = composite->operand(at);
      } else if (composite->opcode == spv::OpTypeArray) {
        path += "[" + std::to_string(at) + "]";
        type = composite->operand(0);
      } else {
        return {};
      }
    }
  return path;
}

// Whether two output paths overlap (one is the other or a part of it).
bool pathsOverlap(const std::string& a, const std::string& b) {
  const std::string& shorter = a.size() <= b.size() ? a : b;
  const std::string& longer = a.size() <= b.size() ? b : a;
  return longer.compare(0, shorter.size(), shorter) == 0 &&
         (longer.size() == shorter.size() || longer[shorter.size()] == '.' || longer[shorter.size()] == '[');
}

class HaloPass final : public Pass {
 public:
  const char* name() const override { return "halo"; }

  PassResult run(PassContext& ctx) override {
    if (!ctx.shiftPosition || !ctx.options.haloFix || !ctx.eyeDeclared)
      return PassResult::Unchanged;
    auto& m = ctx.module;

    // Which values are the mono position, and through which pointers it is written: the shared
    // clip-position analysis (its mono values follow copies kept in function-local variables).
    const ClipPositionAnalysis& positions = ctx.analyses.clipPositions();
    const std::set<uint32_t>& positionValues = positions.monoValues();
    std::set<uint32_t> positionOutputs;
    for (const auto& p : positions.outputs()) positionOutputs.insert(p.variable);
    std::set<uint32_t> builtinOutputs;
    for (uint32_t id : m.entryInterface())
      if (m.hasDecoration(id, spv::DecorationBuiltIn)) builtinOutputs.insert(id);

    // Equal by value: every value numbered like one of the position's.
    const analysis::ValueNumbers& numbers = ctx.analyses.valueNumbers();
    std::set<uint32_t> positionNumbers;
    for (uint32_t v : positionValues)
      if (auto n = numbers.number(v)) positionNumbers.insert(*n);
    isPosition_ = [&, positionValues](uint32_t v) {
      if (positionValues.count(v)) return true;
      auto n = numbers.number(v);
      return n && positionNumbers.count(*n) > 0;
    };
    exactCopies_.clear();
    std::map<uint32_t, uint32_t> monoStoredTo;  // output -> the mono value its (single) store wrote
    std::vector<std::string> fixed;
    std::vector<std::pair<uint32_t, HaloFacts::ExactCopy>> exactParts;  // output variable, its copy
    std::set<std::string> inexactRoots;  // outputs one of whose shifted stores is not a copy
    std::vector<std::pair<uint32_t, std::optional<HaloFacts::DerivedText>>> derivedTexts;  // per derived store
    if (!positionValues.empty())
      for (auto& fn : m.functions) {
        for (auto& block : fn.blocks) {
          for (size_t i = 0; i < block.instructions.size(); ++i) {
            const Instruction store = block.instructions[i];
            if (store.opcode != spv::OpStore || positions.addressesWholePosition(store.operand(0))) continue;
            uint32_t target = m.rootVariable(store.operand(0));
            if (!target || positionOutputs.count(target) || builtinOutputs.count(target)) continue;
            if (m.storageClassOf(target) != spv::StorageClassOutput) continue;
            std::vector<Instruction> code;
            std::map<uint32_t, uint32_t> cloned;
            uint32_t newValue = cloneWithShift(ctx, store.operand(1), positionValues, code, cloned, 0);
            if (newValue == store.operand(1)) continue;  // not derived from the position
            monoStoredTo[target] = store.operand(1);
            const std::string root = m.name(target).empty() ? std::to_string(target) : m.name(target);
            if (isPosition_(store.operand(1))) {  // equal by value: the splice may copy the shifted position
              exactCopies_.push_back(root);
              exactParts.push_back({target, {root, outputPath(m, store.operand(0))}});
            } else {
              inexactRoots.insert(root);
              derivedTexts.push_back({target, derivedText(m, store, root)});
            }
            block.instructions[i].operands[1] = newValue;
            block.instructions.insert(block.instructions.begin() + static_cast<long>(i), code.begin(), code.end());
            i += code.size();
            m.invalidateDefinitions();
            fixed.push_back(m.name(target).empty() ? std::to_string(target) : m.name(target));
          }
        }
      }
    // Only an output written once has one mono value to read back.
    for (auto it = monoStoredTo.begin(); it != monoStoredTo.end();)
      it = spirv::storesTo(m, it->first) == 1 ? std::next(it) : monoStoredTo.erase(it);
    readBackMonoValues(ctx, monoStoredTo);
    isPosition_ = nullptr;  // it refers to this run's numbering
    shiftExactCopiesSeenAfterInlining(ctx, fixed);
    HaloFacts& facts = ctx.record.halo;
    facts.shiftedOutputs = fixed;
    // The outputs computed from the clip position rather than copies of it: the HLSL source splice
    // shifts copies in the text, these only the IR carries.
    facts.derivedOutputs.clear();
    for (const auto& output : fixed)
      if (inexactRoots.count(output) &&
          std::find(facts.derivedOutputs.begin(), facts.derivedOutputs.end(), output) == facts.derivedOutputs.end())
        facts.derivedOutputs.push_back(output);
    // The derived outputs as text: each stored once, by a store whose computation the text can show.
    facts.derivedTexts.clear();
    for (const auto& [target, text] : derivedTexts) {
      if (!text || spirv::storesTo(m, target) != 1) {
        facts.derivedTexts.clear();
        break;
      }
      facts.derivedTexts.push_back(*text);
    }
    // A copy's part the text can re-copy to: named, and no other store writes any of it; only where
    // the position has one value (re-copying the final position is then the copy's value).
    facts.exactCopies.clear();
    if (positionValues.size() == 1)
      for (const auto& part : exactParts) {
        // Plain variables, not structured bindings: the lambda below captures them (clang 14 cannot).
        const uint32_t target = part.first;
        const HaloFacts::ExactCopy& copy = part.second;
        if (copy.path.empty()) continue;
        int overlapping = 0;
        spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
          if (inst.opcode != spv::OpStore || m.rootVariable(inst.operand(0)) != target) return;
          std::string other = outputPath(m, inst.operand(0));
          if (other.empty() || pathsOverlap(other, copy.path)) ++overlapping;
        });
        if (overlapping == 1) facts.exactCopies.push_back(copy);
      }
    const bool lanesMoved = moveLanesDerivedFromPositionX(ctx, fixed);
    return fixed.empty() && !lanesMoved ? PassResult::Unchanged : PassResult::Changed;
  }

 private:
  std::function<bool(uint32_t)> isPosition_;  // equal by value to the mono position (set per run)

  // The position read back from an output this pass just shifted (`gl_Position = outPos`): the
  // load would now read the shifted value and stereo-shift would shift it again. It reads the mono
  // value the output was computed from instead, where that value is known there: the output's
  // only store, earlier in the same block.
  void readBackMonoValues(PassContext& ctx, const std::map<uint32_t, uint32_t>& monoStoredTo) {
    auto& m = ctx.module;
    const ClipPositionAnalysis& positions = ctx.analyses.clipPositions();
    for (auto& fn : m.functions)
      for (auto& block : fn.blocks) {
        std::map<uint32_t, size_t> storedAt;  // output -> index of its store in this block
        for (size_t i = 0; i < block.instructions.size(); ++i) {
          Instruction& inst = block.instructions[i];
          if (inst.opcode == spv::OpStore && monoStoredTo.count(inst.operand(0))) storedAt[inst.operand(0)] = i;
          if (inst.opcode != spv::OpLoad || !monoStoredTo.count(inst.operand(0)) || !storedAt.count(inst.operand(0))) continue;
          uint32_t loaded = inst.resultId;
          bool feedsPosition = false;
          for (const auto& other : block.instructions)
            if (other.opcode == spv::OpStore && positions.addressesWholePosition(other.operand(0)) && other.operand(1) == loaded)
              feedsPosition = true;
          if (!feedsPosition) continue;
          inst = Instruction(spv::OpCopyObject, inst.typeId, loaded, {monoStoredTo.at(inst.operand(0))});
          m.invalidateDefinitions();
        }
      }
  }
  std::vector<std::string> exactCopies_;

  // Copies made through structs and function calls (HLSL output structs: `o.clip = o.pos;` inside
  // the user's entry, members copied out by glslang's wrapper) are invisible to the local data flow
  // above. Inlining and folding a throw-away copy shows them: an output whose stored value is the
  // very value stored to the position is an exact copy, and its stores in the real module get the
  // same shift applied to their own value.
  void shiftExactCopiesSeenAfterInlining(PassContext& ctx, std::vector<std::string>& fixed) {
    auto& m = ctx.module;
    const auto& outputs = ctx.analyses.clipPositions().outputs();
    if (outputs.size() != 1 || outputs.front().isMember) return;
    const spirv::Module* optimized = ctx.analyses.foldedCopy();
    if (!optimized) return;
    ClipPositionAnalysis foldedPositions(*optimized);  // global ids are the module's own
    std::set<uint32_t> positionValues;
    std::map<uint32_t, std::set<uint32_t>> storedTo;
    for (const auto& fn : optimized->functions)
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions)
          if (inst.opcode == spv::OpStore) {
            if (foldedPositions.addressesWholePosition(inst.operand(0))) positionValues.insert(inst.operand(1));
            else storedTo[inst.operand(0)].insert(inst.operand(1));
          }
    if (positionValues.empty()) return;
    uint32_t v4 = m.typeVector(m.typeFloat(32), 4);
    for (const auto& [variable, values] : storedTo) {
      if (m.storageClassOf(variable) != spv::StorageClassOutput) continue;
      if (m.pointeeType(m.definition(variable)->typeId) != v4) continue;
      if (!std::all_of(values.begin(), values.end(), [&](uint32_t v) { return positionValues.count(v) > 0; })) continue;
      std::string name = m.name(variable).empty() ? std::to_string(variable) : m.name(variable);
      if (std::find(fixed.begin(), fixed.end(), name) != fixed.end()) continue;
      for (auto& fn : m.functions)
        for (auto& block : fn.blocks)
          for (size_t i = 0; i < block.instructions.size(); ++i) {
            if (block.instructions[i].opcode != spv::OpStore || block.instructions[i].operand(0) != variable) continue;
            std::vector<Instruction> code;
            uint32_t shifted = emitShiftedVec4Select(ctx, code, block.instructions[i].operand(1));
            block.instructions[i].operands[1] = shifted;
            block.instructions.insert(block.instructions.begin() + static_cast<long>(i), code.begin(), code.end());
            i += code.size();
          }
      m.invalidateDefinitions();
      fixed.push_back(name);
      exactCopies_.push_back(name);
    }
  }


  // The name the source reads a position load by: a named variable (a local holding the position),
  // or gl_Position, a member of the built-in block. Empty otherwise.
  static std::string loadedName(const spirv::Module& m, uint32_t pointer) {
    const Instruction* def = m.definition(pointer);
    if (def && def->opcode == spv::OpVariable) return m.name(pointer);
    if (!def || def->opcode != spv::OpAccessChain || def->operands.size() != 2) return {};
    const Instruction* base = m.definition(def->operand(0));
    auto index = base && base->opcode == spv::OpVariable ? analysis::constantValue(m, def->operand(1)) : std::nullopt;
    if (!index) return {};
    std::string member = m.memberName(m.pointeeType(base->typeId), *index);
    return member == "gl_Position" ? member : std::string();
  }

  // A derived output's store as a text splice can recompute it (run_record.h, DerivedText), or
  // nullopt: a position value in its computation that is no load of a named place (recomputed
  // `mvp * p`), a name read there as the position and as something else, a part the source does
  // not spell plainly.
  std::optional<HaloFacts::DerivedText> derivedText(const spirv::Module& m, const Instruction& store,
                                                    const std::string& root) {
    HaloFacts::DerivedText text{root, outputPath(m, store.operand(0)), {}};
    if (text.path.empty() || text.path.find_first_of(".[") != std::string::npos) return std::nullopt;
    std::set<std::string> position, other;
    bool plain = true;
    std::function<void(uint32_t, int)> walk = [&](uint32_t value, int depth) {
      const Instruction* def = m.definition(value);
      if (!def || depth > 64) return;
      bool isPosition = isPosition_ && isPosition_(value);
      if (def->opcode == spv::OpLoad) {
        std::string name = loadedName(m, def->operand(0));
        if (isPosition && name.empty()) plain = false;
        (isPosition ? position : other).insert(name);
        return;
      }
      if (isPosition) plain = false;
      if (!isPureArithmetic(def->opcode)) return;
      auto [first, last] = valueOperands(*def);
      for (size_t k = first; k < last; ++k) walk(def->operand(k), depth + 1);
    };
    walk(store.operand(1), 0);
    for (const auto& name : position)
      if (other.count(name)) plain = false;
    if (!plain || position.empty()) return std::nullopt;
    text.positionNames.assign(position.begin(), position.end());
    return text;
  }

  // Returns `value` itself when it does not depend on the position, else the id of a clone computed
  // from the shifted position (instructions appended to `code`).
  uint32_t cloneWithShift(PassContext& ctx, uint32_t value, const std::set<uint32_t>& positionValues,
                          std::vector<Instruction>& code, std::map<uint32_t, uint32_t>& cloned, int depth) {
    if (auto it = cloned.find(value); it != cloned.end()) return it->second;
    auto& m = ctx.module;
    if (positionValues.count(value) || (isPosition_ && isPosition_(value))) {
      uint32_t shifted = emitShiftedVec4Select(ctx, code, value);
      cloned[value] = shifted;
      return shifted;
    }
    const Instruction* def = m.definition(value);
    if (!def || depth > 64 || !isPureArithmetic(def->opcode)) return value;
    Instruction copy = *def;
    bool changed = false;
    auto [first, last] = valueOperands(copy);
    for (size_t k = first; k < last; ++k) {
      uint32_t replaced = cloneWithShift(ctx, copy.operands[k], positionValues, code, cloned, depth + 1);
      if (replaced != copy.operands[k]) {
        copy.operands[k] = replaced;
        changed = true;
      }
    }
    if (!changed) return value;
    copy.resultId = m.takeId();
    code.push_back(copy);
    cloned[value] = copy.resultId;
    return copy.resultId;
  }
};

}  // namespace

std::unique_ptr<Pass> createHaloPass() { return std::make_unique<HaloPass>(); }

// Rewrites stores to other outputs only: the position's pointers and values stay as they were.
PassInfo haloPassInfo() {
  return {"halo", createHaloPass,
          "shifts outputs computed from the clip position (copies, screen UVs) like the position itself",
          "on (--no-halo turns it off)",
          "before the shift, while the only loads of the position are the application's own, so it sees "
          "exactly the values the application derived its outputs from",
          {"clip-position-detection", "eye-params"}, kClipPositionAnalysis | kFoldedCopyAnalysis | kValueNumberAnalysis,
          kKeptByDeclarations, editSet(EditKind::DerivedOutputShift)};
}

}  // namespace stereoshift
