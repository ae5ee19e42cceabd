#include "passes/ir/module.h"

#include "passes/ir/image_instructions.h"

#include <algorithm>
#include <cstring>

namespace stereoshift::spirv {

namespace {

constexpr uint32_t kMagic = 0x07230203;

}  // namespace

std::string Instruction::stringOperand(size_t first) const {
  std::string out;
  for (size_t i = first; i < operands.size(); ++i) {
    uint32_t word = operands[i];
    for (int b = 0; b < 4; ++b) {
      char c = static_cast<char>((word >> (8 * b)) & 0xff);
      if (c == 0) return out;
      out.push_back(c);
    }
  }
  return out;
}

size_t Instruction::stringWordCount(size_t first) const {
  return stringOperand(first).size() / 4 + 1;
}

void Instruction::appendTo(std::vector<uint32_t>& words) const {
  uint32_t count = 1 + (typeId ? 1 : 0) + (resultId ? 1 : 0) + static_cast<uint32_t>(operands.size());
  words.push_back((count << 16) | static_cast<uint32_t>(opcode));
  if (typeId) words.push_back(typeId);
  if (resultId) words.push_back(resultId);
  words.insert(words.end(), operands.begin(), operands.end());
}

std::vector<uint32_t> encodeString(std::string_view text) {
  std::vector<uint32_t> words(text.size() / 4 + 1, 0);
  for (size_t i = 0; i < text.size(); ++i)
    words[i / 4] |= static_cast<uint32_t>(static_cast<unsigned char>(text[i])) << (8 * (i % 4));
  return words;
}

const Instruction* Block::mergeInstruction() const {
  if (instructions.size() < 2) return nullptr;
  const Instruction& candidate = instructions[instructions.size() - 2];
  if (candidate.opcode == spv::OpSelectionMerge || candidate.opcode == spv::OpLoopMerge)
    return &candidate;
  return nullptr;
}

std::optional<Module> Module::parse(const std::vector<uint32_t>& words, std::string* error) {
  auto fail = [&](const std::string& message) -> std::optional<Module> {
    if (error) *error = message;
    return std::nullopt;
  };
  if (words.size() < 5) return fail("not a SPIR-V module: shorter than its 5-word header");
  if (words[0] != kMagic) return fail("not a SPIR-V module: bad magic number");
  Module module;
  module.version = words[1];
  module.generator = words[2];
  module.bound_ = words[3];
  module.schema = words[4];

  Function* currentFunction = nullptr;
  Block* currentBlock = nullptr;
  size_t at = 5;
  while (at < words.size()) {
    uint32_t count = words[at] >> 16;
    auto op = static_cast<spv::Op>(words[at] & 0xffff);
    if (count == 0 || at + count > words.size())
      return fail("malformed SPIR-V: instruction at word " + std::to_string(at) + " overruns the module");
    bool hasResult = false, hasType = false;
    spv::HasResultAndType(op, &hasResult, &hasType);
    Instruction inst;
    inst.opcode = op;
    size_t w = at + 1;
    if (hasType) inst.typeId = w < at + count ? words[w++] : 0;
    if (hasResult) inst.resultId = w < at + count ? words[w++] : 0;
    inst.operands.assign(words.begin() + static_cast<long>(w), words.begin() + static_cast<long>(at + count));
    at += count;

    if (currentFunction) {
      switch (op) {
        case spv::OpFunctionParameter:
          currentFunction->parameters.push_back(std::move(inst));
          break;
        case spv::OpLabel:
          currentFunction->blocks.push_back(Block{inst.resultId, {}});
          currentBlock = &currentFunction->blocks.back();
          break;
        case spv::OpFunctionEnd:
          currentFunction = nullptr;
          currentBlock = nullptr;
          break;
        default:
          // A line for the function's own definition (before its first block) says nothing the
          // analyses use: dropped.
          if (!currentBlock && (op == spv::OpLine || op == spv::OpNoLine)) break;
          if (!currentBlock) return fail("malformed SPIR-V: instruction outside a block");
          currentBlock->instructions.push_back(std::move(inst));
      }
      continue;
    }
    switch (op) {
      case spv::OpCapability: module.capabilities.push_back(std::move(inst)); break;
      case spv::OpExtension: module.extensions.push_back(std::move(inst)); break;
      case spv::OpExtInstImport: module.extInstImports.push_back(std::move(inst)); break;
      case spv::OpMemoryModel: module.memoryModel.push_back(std::move(inst)); break;
      case spv::OpEntryPoint: module.entryPoints.push_back(std::move(inst)); break;
      case spv::OpExecutionMode: case spv::OpExecutionModeId:
        module.executionModes.push_back(std::move(inst)); break;
      case spv::OpString: case spv::OpSource: case spv::OpSourceContinued: case spv::OpSourceExtension:
        module.debugSource.push_back(std::move(inst)); break;
      case spv::OpName: case spv::OpMemberName: module.debugNames.push_back(std::move(inst)); break;
      case spv::OpModuleProcessed: module.debugModuleProcessed.push_back(std::move(inst)); break;
      case spv::OpDecorate: case spv::OpMemberDecorate: case spv::OpDecorationGroup:
      case spv::OpGroupDecorate: case spv::OpGroupMemberDecorate: case spv::OpDecorateId:
      case spv::OpDecorateString: case spv::OpMemberDecorateString:
        module.annotations.push_back(std::move(inst)); break;
      case spv::OpFunction:
        module.functions.push_back(Function{std::move(inst), {}, {}});
        currentFunction = &module.functions.back();
        break;
      default:
        module.typesValues.push_back(std::move(inst));
    }
  }
  if (currentFunction) return fail("malformed SPIR-V: function without OpFunctionEnd");
  if (module.memoryModel.empty()) return fail("malformed SPIR-V: no OpMemoryModel");
  return module;
}

std::vector<uint32_t> Module::encode() const {
  std::vector<uint32_t> words = {kMagic, version, generator, bound_, schema};
  for (const auto* section : {&capabilities, &extensions, &extInstImports, &memoryModel, &entryPoints,
                              &executionModes, &debugSource, &debugNames, &debugModuleProcessed,
                              &annotations, &typesValues})
    for (const auto& inst : *section) inst.appendTo(words);
  for (const auto& fn : functions) {
    fn.definition.appendTo(words);
    for (const auto& p : fn.parameters) p.appendTo(words);
    for (const auto& block : fn.blocks) {
      Instruction(spv::OpLabel, 0, block.labelId).appendTo(words);
      for (const auto& inst : block.instructions) inst.appendTo(words);
    }
    Instruction(spv::OpFunctionEnd, 0, 0).appendTo(words);
  }
  return words;
}

void Module::rebuildDefinitions() const {
  defs_.clear();
  for (const auto* section : {&extInstImports, &debugSource, &typesValues})
    for (const auto& inst : *section)
      if (inst.resultId) defs_[inst.resultId] = &inst;
  for (const auto& fn : functions) {
    defs_[fn.definition.resultId] = &fn.definition;
    for (const auto& p : fn.parameters) defs_[p.resultId] = &p;
    for (const auto& block : fn.blocks)
      for (const auto& inst : block.instructions)
        if (inst.resultId) defs_[inst.resultId] = &inst;
  }
  defsValid_ = true;
}

const Instruction* Module::definition(uint32_t id) const {
  if (!defsValid_) rebuildDefinitions();
  auto it = defs_.find(id);
  return it == defs_.end() ? nullptr : it->second;
}

std::string Module::name(uint32_t id) const {
  for (const auto& inst : debugNames)
    if (inst.opcode == spv::OpName && inst.operand(0) == id) return inst.stringOperand(1);
  return {};
}

std::string Module::memberName(uint32_t structId, uint32_t member) const {
  for (const auto& inst : debugNames)
    if (inst.opcode == spv::OpMemberName && inst.operand(0) == structId && inst.operand(1) == member)
      return inst.stringOperand(2);
  return {};
}

std::vector<std::string> Module::allNames() const {
  std::vector<std::string> names;
  for (const auto& inst : debugNames)
    names.push_back(inst.opcode == spv::OpName ? inst.stringOperand(1) : inst.stringOperand(2));
  return names;
}

bool Module::hasDecoration(uint32_t id, spv::Decoration decoration) const {
  for (const auto& inst : annotations)
    if (inst.opcode == spv::OpDecorate && inst.operand(0) == id && inst.operand(1) == uint32_t(decoration))
      return true;
  return false;
}

std::optional<uint32_t> Module::decorationValue(uint32_t id, spv::Decoration decoration) const {
  for (const auto& inst : annotations)
    if (inst.opcode == spv::OpDecorate && inst.operand(0) == id && inst.operand(1) == uint32_t(decoration) &&
        inst.operands.size() > 2)
      return inst.operand(2);
  return std::nullopt;
}

bool Module::hasMemberDecoration(uint32_t structId, uint32_t member, spv::Decoration decoration) const {
  return memberDecorationValue(structId, member, decoration).has_value() ||
         std::any_of(annotations.begin(), annotations.end(), [&](const Instruction& inst) {
           return inst.opcode == spv::OpMemberDecorate && inst.operand(0) == structId &&
                  inst.operand(1) == member && inst.operand(2) == uint32_t(decoration);
         });
}

std::optional<uint32_t> Module::memberDecorationValue(uint32_t structId, uint32_t member,
                                                      spv::Decoration decoration) const {
  for (const auto& inst : annotations)
    if (inst.opcode == spv::OpMemberDecorate && inst.operand(0) == structId && inst.operand(1) == member &&
        inst.operand(2) == uint32_t(decoration) && inst.operands.size() > 3)
      return inst.operand(3);
  return std::nullopt;
}

void Module::removeDecorations(uint32_t id, spv::Decoration decoration) {
  std::erase_if(annotations, [&](const Instruction& inst) {
    return inst.opcode == spv::OpDecorate && inst.operand(0) == id && inst.operand(1) == uint32_t(decoration);
  });
}

void Module::forgetIds(const std::set<uint32_t>& ids) {
  auto targets = [&](const Instruction& inst) { return ids.count(inst.operand(0)) > 0; };
  std::erase_if(debugNames, targets);
  std::erase_if(annotations, [&](const Instruction& inst) {
    return (inst.opcode == spv::OpDecorate || inst.opcode == spv::OpDecorateId || inst.opcode == spv::OpDecorateString ||
            inst.opcode == spv::OpMemberDecorate || inst.opcode == spv::OpMemberDecorateString) &&
           targets(inst);
  });
}

uint32_t Module::findType(spv::Op op, const std::vector<uint32_t>& operands) const {
  for (const auto& inst : typesValues)
    if (inst.opcode == op && inst.operands == operands) return inst.resultId;
  return 0;
}

uint32_t Module::findConstant(uint32_t type, spv::Op op, const std::vector<uint32_t>& operands) const {
  for (const auto& inst : typesValues)
    if (inst.opcode == op && inst.typeId == type && inst.operands == operands && !hasDecoration(inst.resultId, spv::DecorationSpecId))
      return inst.resultId;
  return 0;
}

bool Module::hasCapability(spv::Capability capability) const {
  for (const auto& inst : capabilities)
    if (inst.operand(0) == uint32_t(capability)) return true;
  return false;
}

spv::ExecutionModel Module::executionModel() const {
  return entryPoints.empty() ? spv::ExecutionModelMax
                             : static_cast<spv::ExecutionModel>(entryPoints.front().operand(0));
}

std::string Module::entryPointName() const {
  return entryPoints.empty() ? std::string() : entryPoints.front().stringOperand(2);
}

uint32_t Module::entryFunctionId() const {
  return entryPoints.empty() ? 0 : entryPoints.front().operand(1);
}

std::vector<uint32_t> Module::entryInterface() const {
  if (entryPoints.empty()) return {};
  const auto& entry = entryPoints.front();
  size_t first = 2 + entry.stringWordCount(2);
  return {entry.operands.begin() + static_cast<long>(first), entry.operands.end()};
}

Function* Module::function(uint32_t id) {
  for (auto& fn : functions)
    if (fn.id() == id) return &fn;
  return nullptr;
}

const Function* Module::function(uint32_t id) const {
  for (const auto& fn : functions)
    if (fn.id() == id) return &fn;
  return nullptr;
}

bool Module::isOpaqueType(uint32_t type) const {
  const Instruction* def = definition(type);
  while (def && (def->opcode == spv::OpTypeArray || def->opcode == spv::OpTypeRuntimeArray))
    def = definition(def->operand(0));
  return def && (def->opcode == spv::OpTypeImage || def->opcode == spv::OpTypeSampler ||
                 def->opcode == spv::OpTypeSampledImage || def->opcode == spv::OpTypeAccelerationStructureKHR);
}

std::optional<spv::StorageClass> Module::storageClassOf(uint32_t pointerId) const {
  const Instruction* def = definition(pointerId);
  if (!def) return std::nullopt;
  const Instruction* type = definition(def->typeId);
  if (!type || type->opcode != spv::OpTypePointer) return std::nullopt;
  return static_cast<spv::StorageClass>(type->operand(0));
}

uint32_t Module::pointeeType(uint32_t pointerTypeId) const {
  const Instruction* type = definition(pointerTypeId);
  return type && type->opcode == spv::OpTypePointer ? type->operand(1) : 0;
}


// Whether operand word k of an instruction in a function body may hold a value id (literals such
// as extract indices, shuffle components, memory and image operand masks never do). Labels are
// reported as ids or not at will: they are never the value being replaced.
uint32_t interfaceLocationCount(const Module& m, uint32_t type) {
  const Instruction* def = m.definition(type);
  if (!def) return 1;
  switch (def->opcode) {
    case spv::OpTypeMatrix: return def->operand(1) * interfaceLocationCount(m, def->operand(0));
    case spv::OpTypeArray: {
      const Instruction* length = m.definition(def->operand(1));
      uint32_t count = length && length->opcode == spv::OpConstant ? length->operand(0) : 1;
      return count * interfaceLocationCount(m, def->operand(0));
    }
    case spv::OpTypeStruct: {
      uint32_t total = 0;
      for (uint32_t member : def->operands) total += interfaceLocationCount(m, member);
      return total;
    }
    case spv::OpTypeVector: {
      const Instruction* component = m.definition(def->operand(0));
      bool wide = component && component->operand(0) == 64;
      return wide && def->operand(1) > 2 ? 2 : 1;
    }
    default: return 1;
  }
}

bool isValueOperand(const Instruction& inst, size_t k) {
  switch (inst.opcode) {
    case spv::OpLoad: return k == 0;
    case spv::OpStore: case spv::OpCopyMemory: return k < 2;
    case spv::OpCompositeExtract: return k == 0;
    case spv::OpCompositeInsert: case spv::OpVectorShuffle: return k < 2;
    case spv::OpExtInst: return k != 1;
    case spv::OpSelectionMerge: case spv::OpLoopMerge: case spv::OpBranch: return false;
    case spv::OpBranchConditional: case spv::OpSwitch: return k == 0;
    case spv::OpVariable: return k == 1;
    case spv::OpLine: case spv::OpNoLine: return false;
    default:
      if (auto image = imageAccess(inst.opcode)) return static_cast<int>(k) != image->imageOperandsMask;
      return true;
  }
}

std::optional<float> Module::floatConstant(uint32_t id) const {
  const Instruction* def = definition(id);
  if (!def || def->opcode != spv::OpConstant) return std::nullopt;
  const Instruction* type = definition(def->typeId);
  if (!type || type->opcode != spv::OpTypeFloat || type->operand(0) != 32) return std::nullopt;
  float value;
  uint32_t bits = def->operand(0);
  std::memcpy(&value, &bits, 4);
  return value;
}

uint32_t Module::rootVariable(uint32_t pointer) const {
  for (int depth = 0; depth < 16; ++depth) {
    const Instruction* def = definition(pointer);
    if (!def) return 0;
    if (def->opcode == spv::OpVariable) return pointer;
    if (def->opcode != spv::OpAccessChain && def->opcode != spv::OpInBoundsAccessChain) return 0;
    pointer = def->operand(0);
  }
  return 0;
}

}  // namespace stereoshift::spirv
