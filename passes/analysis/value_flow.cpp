#include "passes/analysis/value_flow.h"

#include "passes/ir/walker.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <deque>
#include <unordered_set>

namespace stereoshift::analysis {

using spirv::Instruction;

bool pathPrefixOf(const AccessPath& prefix, const AccessPath& full) {
  if (prefix.size() > full.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (prefix[i] != full[i] && prefix[i] != kAnyIndex && full[i] != kAnyIndex) return false;
  return true;
}

bool isComponentwiseGlslInstruction(uint32_t glslInstruction) {
  switch (glslInstruction) {
    case GLSLstd450Length: case GLSLstd450Distance: case GLSLstd450Cross: case GLSLstd450Normalize:
    case GLSLstd450FaceForward: case GLSLstd450Reflect: case GLSLstd450Refract:
    case GLSLstd450Determinant: case GLSLstd450MatrixInverse:
    case GLSLstd450PackSnorm4x8: case GLSLstd450PackUnorm4x8: case GLSLstd450PackSnorm2x16:
    case GLSLstd450PackUnorm2x16: case GLSLstd450PackHalf2x16: case GLSLstd450PackDouble2x32:
    case GLSLstd450UnpackSnorm2x16: case GLSLstd450UnpackUnorm2x16: case GLSLstd450UnpackHalf2x16:
    case GLSLstd450UnpackSnorm4x8: case GLSLstd450UnpackUnorm4x8: case GLSLstd450UnpackDouble2x32:
    case GLSLstd450Modf: case GLSLstd450ModfStruct: case GLSLstd450FrexpStruct:
      return false;
    default:
      return true;
  }
}

ValueFlow::ValueFlow(const spirv::Module& module) : module_(module), defUse_(module) {
  for (const auto& fn : module.functions)
    for (size_t i = 0; i < fn.parameters.size(); ++i) parameterOf_[fn.parameters[i].resultId] = {fn.id(), i};
  spirv::forEachFunctionInstruction(module, [&](const Instruction& inst, const spirv::Function& fn,
                                                const spirv::Block&) {
    switch (inst.opcode) {
      case spv::OpStore: case spv::OpCopyMemory:
        if (auto target = resolvePointer(inst.operand(0))) writesTo_[target->root].push_back({&inst, target->path});
        break;
      case spv::OpLoad:
        if (auto target = resolvePointer(inst.operand(0))) loadsFrom_[target->root].push_back(&inst);
        break;
      case spv::OpFunctionCall:
        callsTo_[inst.operand(0)].push_back(&inst);
        for (size_t k = 1; k < inst.operands.size(); ++k)
          if (auto target = resolvePointer(inst.operands[k]))
            pointerArguments_[target->root].push_back({inst.operand(0), k - 1});
        break;
      case spv::OpReturnValue:
        returnsOf_[fn.id()].push_back(inst.operand(0));
        break;
      default:
        break;
    }
  });
}

std::optional<PointerTarget> ValueFlow::resolvePointer(uint32_t pointer) const {
  AccessPath reversed;
  for (int depth = 0; depth < 64; ++depth) {
    const Instruction* def = definition(pointer);
    if (!def) return std::nullopt;
    switch (def->opcode) {
      case spv::OpVariable: case spv::OpFunctionParameter:
        return PointerTarget{pointer, AccessPath(reversed.rbegin(), reversed.rend())};
      case spv::OpAccessChain: case spv::OpInBoundsAccessChain:
        for (size_t k = def->operands.size(); k-- > 1;) {
          const Instruction* index = definition(def->operands[k]);
          reversed.push_back(index && index->opcode == spv::OpConstant ? index->operand(0) : kAnyIndex);
        }
        pointer = def->operand(0);
        break;
      case spv::OpCopyObject:
        pointer = def->operand(0);
        break;
      default:
        return std::nullopt;
    }
  }
  return std::nullopt;
}

namespace {
template <class Map>
const typename Map::mapped_type& findOrEmpty(const Map& map, uint32_t key) {
  static const typename Map::mapped_type kEmpty;
  auto it = map.find(key);
  return it == map.end() ? kEmpty : it->second;
}
}  // namespace

const std::vector<ValueFlow::Write>& ValueFlow::writesTo(uint32_t root) const { return findOrEmpty(writesTo_, root); }

const std::vector<const Instruction*>& ValueFlow::loadsFrom(uint32_t root) const {
  return findOrEmpty(loadsFrom_, root);
}

const std::vector<const Instruction*>& ValueFlow::callsTo(uint32_t function) const {
  return findOrEmpty(callsTo_, function);
}

const std::vector<uint32_t>& ValueFlow::returnsOf(uint32_t function) const { return findOrEmpty(returnsOf_, function); }

std::optional<ValueFlow::ParameterPosition> ValueFlow::parameterOf(uint32_t id) const {
  auto it = parameterOf_.find(id);
  if (it == parameterOf_.end()) return std::nullopt;
  return it->second;
}

const std::vector<ValueFlow::ParameterPosition>& ValueFlow::pointerArgumentsOf(uint32_t root) const {
  return findOrEmpty(pointerArguments_, root);
}

ValueFlow::Flags ValueFlow::operandFlags(const Instruction& inst, const FlagMap& flags, int* flaggedOperands) {
  Flags all = 0;
  int count = 0;
  for (size_t k = 0; k < inst.operands.size(); ++k)
    if (spirv::isValueOperand(inst, k))
      if (Flags f = flagsOf(flags, inst.operands[k])) {
        all |= f;
        ++count;
      }
  if (flaggedOperands) *flaggedOperands = count;
  return all;
}

// A worklist on the def-use lists does the work: when an id gains flags, its users (and, for a
// variable, its loads) are looked at again. Rules may also read ids that are not operands (two
// levels up, say), which the worklist would not notice, so a whole-module sweep closes each
// round: the run ends when a sweep changes nothing, at the least fixed point of the rules.
ValueFlow::FlagMap ValueFlow::propagate(const FlagMap& seeds, ForwardRules& rules) const {
  FlagMap flags;
  for (const auto& [id, f] : seeds)
    if (f) flags[id] = f;
  std::deque<const Instruction*> work;
  std::unordered_set<const Instruction*> queued;
  size_t raises = 0;
  auto enqueue = [&](const Instruction* inst) {
    if (queued.insert(inst).second) work.push_back(inst);
  };
  auto raise = [&](uint32_t id, Flags f) {
    Flags& slot = flags[id];
    if ((slot | f) == slot) return;
    slot |= f;
    ++raises;
    for (const spirv::Use& use : defUse_.uses(id)) enqueue(use.user);
    for (const Instruction* load : loadsFrom(id)) enqueue(load);
  };
  auto evaluate = [&](const Instruction& inst) {
    if (inst.opcode == spv::OpStore) {
      Flags f = flagsOf(flags, inst.operand(1));
      if (!f) return;
      auto target = resolvePointer(inst.operand(0));
      if (target && rules.storeCarries(inst, target->root, f)) raise(target->root, f);
      return;
    }
    if (inst.opcode == spv::OpLoad) {
      auto target = resolvePointer(inst.operand(0));
      if (Flags f = target ? flagsOf(flags, target->root) : 0) raise(inst.resultId, f);
      return;
    }
    if (!inst.resultId) return;
    if (Flags f = rules.resultFlags(inst, flags)) raise(inst.resultId, f);
  };
  for (bool firstRound = true;; firstRound = false) {
    size_t before = raises;
    spirv::forEachFunctionInstruction(
        module_, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) { evaluate(inst); });
    if (!firstRound && raises == before) break;
    while (!work.empty()) {
      const Instruction* inst = work.front();
      work.pop_front();
      queued.erase(inst);
      evaluate(*inst);
    }
  }
  return flags;
}

}  // namespace stereoshift::analysis
