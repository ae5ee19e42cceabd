// See stage_interface.h. The view-vector flow answers what each input becomes; this file only
// walks the interface and names what the other stage links to.
#include "passes/analysis/stage_interface.h"

#include "passes/analysis/uniform_slots.h"
#include "passes/ir/walker.h"

#include <functional>
#include <map>

namespace stereoshift::analysis {

using spirv::Instruction;
using spirv::Module;

InterfaceSlot interfaceSlot(const Module& m, uint32_t variable, int64_t member) {
  InterfaceSlot slot;
  slot.location = m.decorationValue(variable, spv::DecorationLocation);
  slot.builtin = m.hasDecoration(variable, spv::DecorationBuiltIn);
  slot.name = m.name(variable);
  if (member < 0) {
    slot.display = slot.name.empty() ? std::to_string(variable) : slot.name;
    return slot;
  }
  uint32_t block = m.pointeeType(m.definition(variable)->typeId);
  const Instruction* def = m.definition(block);
  while (def && def->opcode == spv::OpTypeArray) {  // a per-vertex array (`gs_in[]`): its element block
    block = def->operand(0);
    def = m.definition(block);
  }
  auto index = static_cast<uint32_t>(member);
  slot.blockName = m.name(block);
  slot.name = m.memberName(block, index);
  slot.display = (m.name(variable).empty() ? slot.blockName : m.name(variable)) + "." + slot.name;
  slot.builtin |= m.hasMemberDecoration(block, index, spv::DecorationBuiltIn);
  if (slot.location && def)
    for (uint32_t i = 0; i < index && i < def->operands.size(); ++i) *slot.location += spirv::interfaceLocationCount(m, def->operands[i]);
  return slot;
}


const StageInputUse* consumerOf(const NextStageFacts* next, const Module& m, const OutputSlot& output) {
  if (!next) return nullptr;
  InterfaceSlot ours = interfaceSlot(m, output.variable, output.member);
  for (const auto& input : next->inputs) {
    if (next->linkByName ? (!ours.name.empty() && input.name == ours.name && input.blockName == ours.blockName)
                         : (ours.location && input.hasLocation && input.location == *ours.location))
      return &input;
  }
  return nullptr;
}

bool passesCameraCandidate(const Module& m) {
  if (m.executionModel() == spv::ExecutionModelFragment) return false;  // nothing after it to pass to
  return spirv::anyFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (isGlslExtInst(m, inst, {GLSLstd450MatrixInverse})) return true;
    if (inst.opcode != spv::OpLoad) return false;
    auto storage = m.storageClassOf(inst.operand(0));
    if (!storage || !isUniformStorage(*storage)) return false;
    const Instruction* type = m.definition(inst.typeId);
    if (type && type->opcode == spv::OpTypeStruct) return true;  // a whole-struct load of a camera block
    if (!type || type->opcode != spv::OpTypeVector || type->operand(1) < 3) return false;
    const Instruction* component = m.definition(type->operand(0));
    return component && component->opcode == spv::OpTypeFloat;
  });
}

bool hasVectorSubtraction(const Module& m) {
  return spirv::anyFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFSub) return false;
    const Instruction* type = m.definition(inst.typeId);
    return type && type->opcode == spv::OpTypeVector && type->operand(1) >= 3;
  });
}

namespace {

uint32_t perVertexType(const Module& m, uint32_t variableType) {
  const Instruction* def = m.definition(variableType);
  while (def && (def->opcode == spv::OpTypeArray || def->opcode == spv::OpTypeRuntimeArray)) def = m.definition(def->operand(0));
  return def ? def->resultId : 0;
}


// Every stage input (a loose variable, or one member of an input block), each described by
// `analyse` from the values that read it.
using DescribeInput = std::function<void(StageInputUse&, ViewVectorFlow&, const std::map<uint32_t, uint8_t>&)>;

NextStageFacts listStageInputs(const Module& module, const Module* folded, ViewVectorFlow* flow, const SourceInfo& source,
                               const std::string& file, const DescribeInput& analyse) {
  NextStageFacts facts;
  facts.file = file;
  facts.linkByName = source.language == SourceLanguage::Glsl && !source.vulkan;
  const Module& m = folded ? *folded : module;  // global ids are shared
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassInput) continue;
    if (m.hasDecoration(inst.resultId, spv::DecorationBuiltIn)) continue;
    const Instruction* block = m.definition(perVertexType(m, m.pointeeType(inst.typeId)));
    bool isBlock = block && block->opcode == spv::OpTypeStruct && m.hasDecoration(block->resultId, spv::DecorationBlock);
    if (!isBlock) {
      StageInputUse use;
      use.name = m.name(inst.resultId);
      if (auto location = m.decorationValue(inst.resultId, spv::DecorationLocation)) {
        use.location = *location;
        use.hasLocation = true;
      }
      if (flow) analyse(use, *flow, {{inst.resultId, kDerived}});
      facts.inputs.push_back(use);
      continue;
    }
    // `in VS_OUT { ... } fs_in;`: member by member, each from the loads that read it (a load of the
    // whole block reads them all). Behind the vertex index of an arrayed input (`gs_in[i].member`),
    // the member is the chain's second index.
    const bool arrayed = block->resultId != m.pointeeType(inst.typeId);
    const size_t memberOperand = arrayed ? 2 : 1;
    for (uint32_t member = 0; member < block->operands.size(); ++member) {
      InterfaceSlot slot = interfaceSlot(m, inst.resultId, member);
      if (slot.builtin) continue;
      StageInputUse use;
      use.name = slot.name;
      use.blockName = slot.blockName;
      if (slot.location) {
        use.location = *slot.location;
        use.hasLocation = true;
      }
      std::map<uint32_t, uint8_t> loads;
      spirv::forEachFunctionInstruction(m, [&](const Instruction& load, const spirv::Function&, const spirv::Block&) {
        if (load.opcode != spv::OpLoad || m.rootVariable(load.operand(0)) != inst.resultId) return;
        const Instruction* chain = m.definition(load.operand(0));
        bool isChain = chain && (chain->opcode == spv::OpAccessChain || chain->opcode == spv::OpInBoundsAccessChain);
        bool whole = chain && (chain->opcode == spv::OpVariable || (arrayed && isChain && chain->operands.size() == 2));
        bool thisMember = isChain && chain->operands.size() > memberOperand &&
                          constantValue(m, chain->operand(memberOperand)) == member;
        if (whole || thisMember) loads[load.resultId] = kDerived;
      });
      if (!loads.empty() && flow) analyse(use, *flow, loads);
      facts.inputs.push_back(use);
    }
  }
  return facts;
}

// What a stage that is read last (the fragment stage) does with an input, from the values that read it.
void describeLastStageInput(StageInputUse& use, ViewVectorFlow& flow, const std::map<uint32_t, uint8_t>& asRead) {
  auto sinks = flow.follow(asRead);
  use.read = sinks.anyUse;
  use.feedsTexcoordAsDirection = (sinks.texcoord & kOffset) != 0;
  for (uint32_t difference : sinks.subtractions)
    if (flow.follow({{difference, kDerived}}).texcoord & kOffset) use.subtractedForOffset = true;
  std::map<uint32_t, uint8_t> asDirection;
  for (const auto& [id, f] : asRead) asDirection[id] = f | kDirection;
  use.feedsTexcoord = (flow.follow(asDirection).texcoord & kOffset) != 0;
}

}  // namespace

NextStageFacts describeStageInputUses(const Module& module, const Module* folded, ViewVectorFlow* flow,
                                      const SourceInfo& source, const std::string& file,
                                      const NextStageFacts* consumer) {
  if (!consumer) return listStageInputs(module, folded, flow, source, file, describeLastStageInput);
  // A stage between: what the stage after does with the outputs an input is written to (a
  // pass-through, or arithmetic on the way) is what it does with the input.
  NextStageFacts facts = listStageInputs(
      module, folded, flow, source, file,
      [&](StageInputUse& use, ViewVectorFlow& flow, const std::map<uint32_t, uint8_t>& asRead) {
        auto sinks = flow.follow(asRead);
        use.read = sinks.anyUse;
        for (const auto& [output, flags] : sinks.outputs) {
          const StageInputUse* after = consumerOf(consumer, flow.module(), output);
          if (!after) continue;
          use.read |= after->read;
          use.feedsTexcoord |= after->feedsTexcoord;
          use.feedsTexcoordAsDirection |= after->feedsTexcoordAsDirection;
          use.subtractedForOffset |= after->subtractedForOffset;
        }
      });
  facts.file = consumer->file + " (through " + file + ")";
  return facts;
}

}  // namespace stereoshift::analysis
