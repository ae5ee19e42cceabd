#include "test/harness/capture_instrument.h"

#include <algorithm>
#include <climits>

namespace stereoshift::harness {

using spirv::Instruction;

const CapturedField* CaptureLayout::position() const {
  for (const auto& f : fields)
    if (f.isPosition) return &f;
  return nullptr;
}

namespace {

// Component count of a 32-bit scalar/vector type, 0 for anything else.
uint32_t componentsOf(const spirv::Module& m, uint32_t type, bool* isFloat) {
  const Instruction* def = m.definition(type);
  if (!def) return 0;
  if (def->opcode == spv::OpTypeFloat || def->opcode == spv::OpTypeInt) {
    if (def->operand(0) != 32) return 0;
    *isFloat = def->opcode == spv::OpTypeFloat;
    return 1;
  }
  if (def->opcode == spv::OpTypeVector) {
    uint32_t n = componentsOf(m, def->operand(0), isFloat);
    return n == 1 ? def->operand(1) : 0;
  }
  return 0;
}

}  // namespace

bool instrumentForCapture(spirv::Module& m, CaptureLayout* layout, std::vector<std::string>* skipped,
                          std::string* error) {
  if (m.entryPoints.empty()) {
    *error = "no entry point";
    return false;
  }
  struct Candidate {
    uint32_t variable;
    bool member;
    uint32_t memberIndex;
    uint32_t location;
    uint32_t components;
    bool isFloat;
    bool isPosition;
    std::string name;
  };
  std::vector<Candidate> candidates;
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->opcode != spv::OpVariable || var->operand(0) != spv::StorageClassOutput) continue;
    uint32_t type = m.pointeeType(var->typeId);
    const Instruction* typeDef = m.definition(type);
    if (!typeDef) continue;
    if (typeDef->opcode == spv::OpTypeStruct) {  // gl_PerVertex: capture only gl_Position
      for (uint32_t i = 0; i < typeDef->operands.size(); ++i)
        if (m.memberDecorationValue(type, i, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInPosition))
          candidates.push_back({id, true, i, UINT32_MAX, 4, true, true, "gl_Position"});
      continue;
    }
    auto builtin = m.decorationValue(id, spv::DecorationBuiltIn);
    if (builtin && *builtin != uint32_t(spv::BuiltInPosition)) continue;  // point size, clip distance
    bool isFloat = true;
    uint32_t components = componentsOf(m, type, &isFloat);
    std::string name = m.name(id).empty() ? "_" + std::to_string(id) : m.name(id);
    if (components == 0) {
      if (skipped) skipped->push_back(name);
      continue;
    }
    bool isPosition = builtin.has_value();
    uint32_t location = isPosition ? UINT32_MAX : m.decorationValue(id, spv::DecorationLocation).value_or(UINT32_MAX - 1);
    candidates.push_back({id, false, 0, location, components, isFloat, isPosition, isPosition ? "gl_Position" : name});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.isPosition != b.isPosition) return a.isPosition;
    return a.location < b.location;
  });
  if (candidates.empty() || !candidates.front().isPosition) {
    *error = "the shader writes no clip position to capture";
    return false;
  }
  uint32_t offset = 0;
  layout->fields.clear();
  for (const auto& c : candidates) {
    layout->fields.push_back({c.name, c.location, offset, c.components, c.isPosition, c.isFloat});
    offset += 4 * c.components;
  }
  layout->stride = offset;

  m.addCapability(spv::CapabilityTransformFeedback);
  m.executionModes.emplace_back(spv::OpExecutionMode, 0, 0,
                                std::vector<uint32_t>{m.entryFunctionId(), uint32_t(spv::ExecutionModeXfb)});
  for (size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    m.decorate(c.variable, spv::DecorationXfbBuffer, {0});
    m.decorate(c.variable, spv::DecorationXfbStride, {layout->stride});
    if (c.member)
      m.decorateMember(m.pointeeType(m.definition(c.variable)->typeId), c.memberIndex, spv::DecorationOffset,
                       {layout->fields[i].offset});
    else
      m.decorate(c.variable, spv::DecorationOffset, {layout->fields[i].offset});
  }
  return true;
}

}  // namespace stereoshift::harness
