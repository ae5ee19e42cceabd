// See builder.h. Every instruction the passes add is made in this file: in a function body by the
// Builder and splitBlock, in the module's sections (names, decorations, types, constants, global
// variables, capabilities, extensions, execution modes) by the Module's adders below, which reuse
// what the module has and keep its definitions current.
#include "passes/ir/builder.h"

#include <cstring>

namespace stereoshift::spirv {

size_t splitBlock(Module& module, Function& fn, size_t index, size_t at, uint32_t restLabel) {
  Block& head = fn.blocks[index];
  const uint32_t headLabel = head.labelId;
  Block rest{restLabel, {}};
  rest.instructions.assign(head.instructions.begin() + static_cast<long>(at), head.instructions.end());
  head.instructions.resize(at);
  for (auto& block : fn.blocks)
    for (auto& inst : block.instructions) {
      if (inst.opcode != spv::OpPhi) continue;
      for (size_t k = 1; k < inst.operands.size(); k += 2)
        if (inst.operands[k] == headLabel) inst.operands[k] = restLabel;
    }
  fn.blocks.insert(fn.blocks.begin() + static_cast<long>(index) + 1, std::move(rest));
  module.invalidateDefinitions();
  return index + 1;
}

// The module's adders (module.h).

void Module::setName(uint32_t id, std::string_view text) {
  std::vector<uint32_t> ops = {id};
  auto encoded = encodeString(text);
  ops.insert(ops.end(), encoded.begin(), encoded.end());
  for (auto& inst : debugNames)
    if (inst.opcode == spv::OpName && inst.operand(0) == id) {
      inst.operands = std::move(ops);
      return;
    }
  debugNames.emplace_back(spv::OpName, 0, 0, std::move(ops));
}

void Module::setMemberName(uint32_t structId, uint32_t member, std::string_view text) {
  std::vector<uint32_t> ops = {structId, member};
  auto encoded = encodeString(text);
  ops.insert(ops.end(), encoded.begin(), encoded.end());
  for (auto& inst : debugNames)
    if (inst.opcode == spv::OpMemberName && inst.operand(0) == structId && inst.operand(1) == member) {
      inst.operands = std::move(ops);
      return;
    }
  debugNames.emplace_back(spv::OpMemberName, 0, 0, std::move(ops));
}

void Module::decorate(uint32_t id, spv::Decoration decoration, std::vector<uint32_t> literals) {
  std::vector<uint32_t> ops = {id, uint32_t(decoration)};
  ops.insert(ops.end(), literals.begin(), literals.end());
  annotations.emplace_back(spv::OpDecorate, 0, 0, std::move(ops));
}

void Module::decorateMember(uint32_t structId, uint32_t member, spv::Decoration decoration,
                            std::vector<uint32_t> literals) {
  std::vector<uint32_t> ops = {structId, member, uint32_t(decoration)};
  ops.insert(ops.end(), literals.begin(), literals.end());
  annotations.emplace_back(spv::OpMemberDecorate, 0, 0, std::move(ops));
}

void Module::decorateString(uint32_t id, spv::Decoration decoration, std::string_view text) {
  std::vector<uint32_t> ops = {id, uint32_t(decoration)};
  for (uint32_t word : encodeString(text)) ops.push_back(word);
  annotations.emplace_back(spv::OpDecorateString, 0, 0, std::move(ops));
}

void Module::addExtension(std::string_view name) {
  for (const auto& inst : extensions)
    if (inst.stringOperand(0) == name) return;
  extensions.emplace_back(spv::OpExtension, 0, 0, encodeString(name));
}

// Types are appended at the end of the types/values section: every operand they refer to already
// exists, so the definition-before-use rule holds.
#define STEREOSHIFT_FIND_OR_ADD_TYPE(op, ...)                           \
  do {                                                                  \
    std::vector<uint32_t> operands = {__VA_ARGS__};                     \
    if (uint32_t found = findType(op, operands)) return found;          \
    uint32_t id = takeId();                                             \
    typesValues.emplace_back(op, 0, id, std::move(operands));           \
    invalidateDefinitions();                                            \
    return id;                                                          \
  } while (0)

uint32_t Module::typeBool() { STEREOSHIFT_FIND_OR_ADD_TYPE(spv::OpTypeBool); }
uint32_t Module::typeInt(uint32_t width, bool isSigned) {
  STEREOSHIFT_FIND_OR_ADD_TYPE(spv::OpTypeInt, width, isSigned ? 1u : 0u);
}
uint32_t Module::typeFloat(uint32_t width) { STEREOSHIFT_FIND_OR_ADD_TYPE(spv::OpTypeFloat, width); }
uint32_t Module::typeVector(uint32_t componentType, uint32_t count) {
  STEREOSHIFT_FIND_OR_ADD_TYPE(spv::OpTypeVector, componentType, count);
}
uint32_t Module::typePointer(spv::StorageClass storage, uint32_t pointee) {
  STEREOSHIFT_FIND_OR_ADD_TYPE(spv::OpTypePointer, uint32_t(storage), pointee);
}
uint32_t Module::typeArray(uint32_t elementType, uint32_t length) {
  uint32_t lengthId = scalarConstant(typeInt(32, false), length);
  STEREOSHIFT_FIND_OR_ADD_TYPE(spv::OpTypeArray, elementType, lengthId);
}
#undef STEREOSHIFT_FIND_OR_ADD_TYPE

uint32_t Module::newStruct(const std::vector<uint32_t>& memberTypes) {
  uint32_t id = takeId();
  typesValues.emplace_back(spv::OpTypeStruct, 0, id, memberTypes);
  invalidateDefinitions();
  return id;
}

uint32_t Module::newArrayType(uint32_t elementType, uint32_t lengthId) {
  uint32_t id = takeId();
  typesValues.emplace_back(spv::OpTypeArray, 0, id, std::vector<uint32_t>{elementType, lengthId});
  invalidateDefinitions();
  return id;
}

uint32_t Module::constantNull(uint32_t type) {
  for (const auto& inst : typesValues)
    if (inst.opcode == spv::OpConstantNull && inst.typeId == type) return inst.resultId;
  const uint32_t id = takeId();
  typesValues.emplace_back(spv::OpConstantNull, type, id);
  invalidateDefinitions();
  return id;
}

uint32_t Module::scalarConstant(uint32_t type, uint32_t bits) {
  if (uint32_t found = findConstant(type, spv::OpConstant, {bits})) return found;
  uint32_t id = takeId();
  typesValues.emplace_back(spv::OpConstant, type, id, std::vector<uint32_t>{bits});
  invalidateDefinitions();
  return id;
}

uint32_t Module::constantFloat(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  return scalarConstant(typeFloat(32), bits);
}

uint32_t Module::constantInt(int32_t value) { return scalarConstant(typeInt(32, true), static_cast<uint32_t>(value)); }

uint32_t Module::specConstantFloat(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  uint32_t type = typeFloat(32);
  uint32_t id = takeId();
  typesValues.emplace_back(spv::OpSpecConstant, type, id, std::vector<uint32_t>{bits});
  invalidateDefinitions();
  return id;
}

uint32_t Module::extInstImport(std::string_view setName) {
  for (const auto& inst : extInstImports)
    if (inst.stringOperand(0) == setName) return inst.resultId;
  uint32_t id = takeId();
  extInstImports.emplace_back(spv::OpExtInstImport, 0, id, encodeString(setName));
  invalidateDefinitions();
  return id;
}

uint32_t Module::addGlobalVariable(uint32_t pointerType, spv::StorageClass storage) {
  uint32_t id = takeId();
  typesValues.emplace_back(spv::OpVariable, pointerType, id, std::vector<uint32_t>{uint32_t(storage)});
  invalidateDefinitions();
  bool listAll = version >= 0x00010400;
  if (listAll || storage == spv::StorageClassInput || storage == spv::StorageClassOutput)
    for (auto& entry : entryPoints) entry.operands.push_back(id);
  return id;
}

void Module::addCapability(spv::Capability capability) {
  if (!hasCapability(capability))
    capabilities.emplace_back(spv::OpCapability, 0, 0, std::vector<uint32_t>{uint32_t(capability)});
}

void Module::addExecutionMode(spv::ExecutionMode mode, std::vector<uint32_t> literals) {
  std::vector<uint32_t> operands = {entryFunctionId(), uint32_t(mode)};
  operands.insert(operands.end(), literals.begin(), literals.end());
  executionModes.emplace_back(spv::OpExecutionMode, 0, 0, std::move(operands));
}

}  // namespace stereoshift::spirv
