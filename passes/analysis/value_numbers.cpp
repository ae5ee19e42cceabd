// See value_numbers.h.
#include "passes/analysis/value_numbers.h"

#include <algorithm>
#include <cstring>

namespace stereoshift::analysis {

using spirv::Instruction;

namespace {

constexpr int kMaxDepth = 64;
// The numbering's budget, in visits: every instruction numbered at the top level and in the calls
// of a few helpers around it. A shader past it has its remaining values numbered on their own.
constexpr uint64_t kVisitsPerInstruction = 64;
constexpr uint64_t kVisitsSlack = 65536;
enum Tag : uint32_t { kConstantTag = 0x80000000u, kReadTag, kComponentTag, kOpTag, kVectorTag };

bool isReadOnlyStorage(spv::StorageClass s) {
  return s == spv::StorageClassInput || s == spv::StorageClassUniform || s == spv::StorageClassUniformConstant ||
         s == spv::StorageClassPushConstant;
}

bool isWrittenStorage(spv::StorageClass s) {
  return s == spv::StorageClassFunction || s == spv::StorageClassPrivate || s == spv::StorageClassOutput;
}

// Pure computations numbered by operation; the rest is opaque.
bool isPure(spv::Op op) {
  switch (op) {
    case spv::OpFAdd: case spv::OpFSub: case spv::OpFMul: case spv::OpFDiv: case spv::OpFNegate: case spv::OpFMod:
    case spv::OpIAdd: case spv::OpISub: case spv::OpIMul: case spv::OpVectorTimesScalar: case spv::OpMatrixTimesScalar:
    case spv::OpMatrixTimesVector: case spv::OpVectorTimesMatrix: case spv::OpMatrixTimesMatrix: case spv::OpDot:
    case spv::OpTranspose: case spv::OpExtInst: case spv::OpSelect: case spv::OpConvertSToF: case spv::OpConvertUToF:
    case spv::OpFOrdLessThan: case spv::OpFOrdGreaterThan: case spv::OpFOrdEqual: case spv::OpCompositeInsert:
      return true;
    default:
      return false;
  }
}

bool isCommutative(spv::Op op) {
  return op == spv::OpFAdd || op == spv::OpFMul || op == spv::OpIAdd || op == spv::OpIMul || op == spv::OpDot ||
         op == spv::OpFOrdEqual;
}

}  // namespace

ValueNumbers::ValueNumbers(const spirv::Module& module) : m_(module) {
  for (const auto& fn : m_.functions) {
    functions_[fn.id()] = &fn;
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions) {
        if (inst.opcode == spv::OpStore || inst.opcode == spv::OpCopyMemory) {
          uint32_t root = m_.rootVariable(inst.operand(0));
          if (root) storesTo_[root].push_back(&inst);
        }
        if (inst.opcode == spv::OpReturnValue) returns_[fn.id()].push_back(inst.operand(0));
      }
  }
  uint64_t instructions = 0;
  for (const auto& fn : m_.functions)
    for (const auto& block : fn.blocks) instructions += block.instructions.size();
  budget_ = kVisitsPerInstruction * instructions + kVisitsSlack;
  contexts_.emplace_back();  // context 0: the top level, nothing bound
  for (const auto& fn : m_.functions)
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions)
        if (inst.resultId) numberOf(inst.resultId, 0, 0);
}

std::optional<uint32_t> ValueNumbers::number(uint32_t id) const {
  auto it = numbers_.find(id);
  if (it == numbers_.end()) return std::nullopt;
  return it->second;
}

uint32_t ValueNumbers::intern(Key key) {
  auto [it, inserted] = interned_.emplace(std::move(key), 0);
  if (inserted) it->second = next_++;
  return it->second;
}

uint32_t ValueNumbers::fresh() { return next_++; }

uint32_t ValueNumbers::numberOf(uint32_t id, Context context, int depth) {
  if (context != 0)
    if (auto bound = contexts_[context].find(id); bound != contexts_[context].end()) return bound->second;
  const uint64_t key = uint64_t{context} << 32 | id;
  if (auto it = numbers_.find(key); it != numbers_.end()) return it->second;
  uint32_t n;
  if (depth > kMaxDepth || visits_ >= budget_) {
    n = fresh();
  } else {
    ++visits_;
    n = compute(id, context, depth + 1);
  }
  // Kept whichever way it was found: a value is one value within its context, and a number of its
  // own (too deep, over the budget) is a safe answer for every later question about it.
  numbers_[key] = n;
  return n;
}

// The context of `call` made from `parent`: the callee's parameters bound to the numbers of the
// call's arguments. nullopt when an argument's value cannot be known (a pointer to memory written
// more than once).
std::optional<ValueNumbers::Context> ValueNumbers::callContext(const Instruction& call, Context parent, int depth) {
  if (auto it = callContexts_.find({parent, call.resultId}); it != callContexts_.end()) return it->second;
  Bindings inner;
  const auto& parameters = functions_.at(call.operand(0))->parameters;
  for (size_t k = 0; k < parameters.size() && k + 1 < call.operands.size(); ++k) {
    uint32_t argument = call.operands[k + 1];
    const Instruction* argDef = m_.definition(argument);
    const Instruction* argType = argDef ? m_.definition(argDef->typeId) : nullptr;
    if (argType && argType->opcode == spv::OpTypePointer) {
      auto held = memoryValue(argument, parent, depth);  // glslang passes copies in locals
      if (!held) return std::nullopt;
      inner[parameters[k].resultId] = *held;
    } else {
      inner[parameters[k].resultId] = numberOf(argument, parent, depth);
    }
  }
  Context context = static_cast<Context>(contexts_.size());
  contexts_.push_back(std::move(inner));
  callContexts_[{parent, call.resultId}] = context;
  // The callee's values in program order, as the top level is numbered: each then finds its
  // operands already numbered, so a long body does not become a deep recursion (which would end in
  // numbers of their own at kMaxDepth).
  for (const auto& block : functions_.at(call.operand(0))->blocks)
    for (const auto& inst : block.instructions)
      if (inst.resultId) numberOf(inst.resultId, context, depth);
  return context;
}

// The number of one component of a vector value: `vec4(p, 1).y` and `p.y` are the same.
uint32_t ValueNumbers::component(uint32_t vector, uint32_t index, Context context, int depth) {
  const Instruction* def = m_.definition(vector);
  if (def && def->opcode == spv::OpCompositeConstruct && depth <= kMaxDepth) {
    const Instruction* type = m_.definition(def->typeId);
    if (type && type->opcode == spv::OpTypeVector) {
      uint32_t at = 0;
      for (uint32_t part : def->operands) {
        const Instruction* partType = m_.definition(m_.definition(part) ? m_.definition(part)->typeId : 0);
        uint32_t size = partType && partType->opcode == spv::OpTypeVector ? partType->operand(1) : 1;
        if (index < at + size) return size == 1 ? numberOf(part, context, depth + 1) : component(part, index - at, context, depth + 1);
        at += size;
      }
    }
  }
  if (def && def->opcode == spv::OpVectorShuffle && depth <= kMaxDepth && index + 2 < def->operands.size()) {
    uint32_t select = def->operands[index + 2];
    const Instruction* first = m_.definition(m_.definition(def->operand(0)) ? m_.definition(def->operand(0))->typeId : 0);
    uint32_t firstSize = first && first->opcode == spv::OpTypeVector ? first->operand(1) : 0;
    if (select != 0xFFFFFFFFu && firstSize)
      return select < firstSize ? component(def->operand(0), select, context, depth + 1)
                                : component(def->operand(1), select - firstSize, context, depth + 1);
  }
  return intern({kComponentTag, numberOf(vector, context, depth + 1), index});
}

// The value a load from `pointer` reads, when that memory is written once, by one whole value.
std::optional<uint32_t> ValueNumbers::memoryValue(uint32_t pointer, Context context, int depth) {
  uint32_t root = m_.rootVariable(pointer);
  if (!root) return std::nullopt;
  const Bindings& bindings = contexts_[context];
  if (auto bound = bindings.find(root); bound != bindings.end() && root == pointer) return bound->second;
  auto storage = m_.storageClassOf(root);
  const Instruction* rootDef = m_.definition(root);
  if (!storage || !rootDef || rootDef->opcode != spv::OpVariable) return std::nullopt;
  if (isReadOnlyStorage(*storage)) {
    Key key = {kReadTag, root};
    for (const Instruction* chain = m_.definition(pointer); chain && chain->opcode != spv::OpVariable;
         chain = m_.definition(chain->operand(0))) {
      if (chain->opcode != spv::OpAccessChain && chain->opcode != spv::OpInBoundsAccessChain) return std::nullopt;
      Key indices;
      for (size_t k = 1; k < chain->operands.size(); ++k) {
        const Instruction* c = m_.definition(chain->operands[k]);
        if (!c || c->opcode != spv::OpConstant) return std::nullopt;  // a run-time index
        indices.push_back(c->operand(0));
      }
      key.insert(key.begin() + 2, indices.begin(), indices.end());
    }
    // `inPos.x` read through an access chain is component 0 of the read of `inPos`.
    uint32_t type = m_.pointeeType(rootDef->typeId), parent = 0;
    for (size_t k = 2; k < key.size(); ++k) {
      const Instruction* t = m_.definition(type);
      if (!t) break;
      parent = type;
      type = t->opcode == spv::OpTypeStruct ? t->operand(key[k]) : t->operand(0);
    }
    const Instruction* parentType = parent ? m_.definition(parent) : nullptr;
    if (parentType && parentType->opcode == spv::OpTypeVector) {
      uint32_t index = key.back();
      key.pop_back();
      return intern({kComponentTag, intern(key), index});
    }
    return intern(key);
  }
  if (!isWrittenStorage(*storage) || pointer != root) return std::nullopt;
  auto stores = storesTo_.find(root);
  if (stores == storesTo_.end() || stores->second.size() != 1) return std::nullopt;
  const Instruction* store = stores->second.front();
  if (store->opcode != spv::OpStore || store->operand(0) != root) return std::nullopt;
  return numberOf(store->operand(1), context, depth + 1);
}

uint32_t ValueNumbers::compute(uint32_t id, Context context, int depth) {
  const Instruction* def = m_.definition(id);
  if (!def) return fresh();
  switch (def->opcode) {
    case spv::OpConstant: case spv::OpConstantTrue: case spv::OpConstantFalse: case spv::OpConstantNull: {
      Key key = {kConstantTag, def->opcode, def->typeId};
      key.insert(key.end(), def->operands.begin(), def->operands.end());
      return intern(key);
    }
    case spv::OpConstantComposite: case spv::OpCompositeConstruct: {
      const Instruction* type = m_.definition(def->typeId);
      if (!type || type->opcode != spv::OpTypeVector) break;
      Key key = {kVectorTag, def->typeId};
      for (uint32_t i = 0; i < type->operand(1); ++i) key.push_back(component(id, i, context, depth));
      return intern(key);
    }
    case spv::OpCopyObject:
      return numberOf(def->operand(0), context, depth);
    case spv::OpLoad:
      if (auto bound = contexts_[context].find(def->operand(0)); bound != contexts_[context].end())
        return bound->second;  // a pointer parameter
      if (auto value = memoryValue(def->operand(0), context, depth)) return *value;
      return fresh();
    case spv::OpCompositeExtract:
      if (def->operands.size() == 2) {
        const Instruction* from = m_.definition(def->operand(0));
        const Instruction* type = from ? m_.definition(from->typeId) : nullptr;
        if (type && type->opcode == spv::OpTypeVector) return component(def->operand(0), def->operand(1), context, depth);
      }
      break;
    case spv::OpVectorShuffle: {
      const Instruction* type = m_.definition(def->typeId);
      if (!type || type->opcode != spv::OpTypeVector) break;
      Key key = {kVectorTag, def->typeId};
      for (uint32_t i = 0; i < type->operand(1); ++i) key.push_back(component(id, i, context, depth));
      return intern(key);
    }
    case spv::OpFunctionCall: {
      auto callee = functions_.find(def->operand(0));
      auto returned = returns_.find(def->operand(0));
      if (callee == functions_.end() || returned == returns_.end() || returned->second.size() != 1) break;
      auto inner = callContext(*def, context, depth);
      if (!inner) return fresh();
      return numberOf(returned->second.front(), *inner, depth);
    }
    default:
      break;
  }
  if (!isPure(def->opcode)) return fresh();
  Key key = {kOpTag, def->opcode, def->typeId};
  Key operands;
  size_t firstLiteral = def->operands.size();
  if (def->opcode == spv::OpCompositeInsert) firstLiteral = 2;
  for (size_t k = 0; k < def->operands.size(); ++k) {
    bool literal = k >= firstLiteral || (def->opcode == spv::OpExtInst && k < 2);
    operands.push_back(literal ? def->operands[k] : numberOf(def->operands[k], context, depth));
  }
  // x * 1.0 and x + 0.0 are x (the optimizer folds them the same way).
  if ((def->opcode == spv::OpFMul || def->opcode == spv::OpFAdd) && operands.size() == 2) {
    for (int side = 0; side < 2; ++side) {
      const Instruction* c = m_.definition(def->operands[side]);
      float one = 1.0f, zero = 0.0f;
      uint32_t neutral;
      std::memcpy(&neutral, def->opcode == spv::OpFMul ? &one : &zero, sizeof neutral);
      if (c && c->opcode == spv::OpConstant && c->operand(0) == neutral && c->typeId == def->typeId)
        return operands[1 - side];
    }
  }
  if (isCommutative(def->opcode) && operands.size() == 2) std::sort(operands.begin(), operands.end());
  key.insert(key.end(), operands.begin(), operands.end());
  return intern(key);
}

}  // namespace stereoshift::analysis
