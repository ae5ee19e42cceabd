#include "transpiler/verify/capture_instrument.h"

#include "passes/ir/builder.h"

#include <algorithm>
#include <climits>
#include <map>
#include <set>

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

Result<CaptureLayout> instrumentForCapture(spirv::Module& m, std::vector<std::string>* skipped) {
  if (m.entryPoints.empty()) return plainError("no entry point");
  CaptureLayout captured, *layout = &captured;
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
  if (candidates.empty() || !candidates.front().isPosition) return plainError("the shader writes no clip position to capture");
  uint32_t offset = 0;
  for (const auto& c : candidates) {
    layout->fields.push_back({c.name, c.location, offset, c.components, c.isPosition, c.isFloat});
    offset += 4 * c.components;
  }
  layout->stride = offset;

  m.addCapability(spv::CapabilityTransformFeedback);
  m.addExecutionMode(spv::ExecutionModeXfb);
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
  return captured;
}

namespace {

// A bool has no size in memory, so SPIR-V allows none in a uniform block (glslang's OpenGL module
// keeps `uniform bool flipY;` as a UniformConstant bool variable, which does not validate either).
// In the harness's default block it is stored as GL stores it, a 32-bit unsigned integer whose any
// nonzero value is true: the unsigned type of the same shape as `type` (bool, bvecN); other types
// as they are.
uint32_t storedAsUint(spirv::Module& m, uint32_t type) {
  const Instruction* d = m.definition(type);
  if (d && d->opcode == spv::OpTypeBool) return m.typeInt(32, false);
  if (d && d->opcode == spv::OpTypeVector) {
    const Instruction* component = m.definition(d->operand(0));
    const uint32_t n = d->operand(1);
    if (component && component->opcode == spv::OpTypeBool) return m.typeVector(m.typeInt(32, false), n);
  }
  return type;
}

// The zero of an integer scalar or vector type (what a stored bool is compared against).
uint32_t nullOf(spirv::Module& m, uint32_t type) {
  return m.constantNull(type);
}

// std140 size and alignment of `type`; arrays get a fresh, strided copy of their type in *type,
// bools (and arrays of them) become the unsigned integers they are stored as (storedAsUint).
// *matrixStride: the column stride of a matrix (or of an array's matrices), 0 for other types.
// Scalars take their own width (a double 8 bytes, a dvec3 / dvec4 32-byte aligned); a matrix is
// stored as an array of its columns, each at least vec4-aligned.
void std140(spirv::Module& m, uint32_t* type, uint32_t* size, uint32_t* align, uint32_t* matrixStride) {
  *type = storedAsUint(m, *type);
  const Instruction* d = m.definition(*type);
  *matrixStride = 0;
  auto scalarBytes = [&](uint32_t scalar) {
    const Instruction* s = m.definition(scalar);
    return s && (s->opcode == spv::OpTypeFloat || s->opcode == spv::OpTypeInt) ? s->operand(0) / 8 : 4u;
  };
  switch (d ? d->opcode : spv::OpNop) {
    case spv::OpTypeFloat: case spv::OpTypeInt:
      *size = *align = d->operand(0) / 8; return;
    case spv::OpTypeVector: {
      const uint32_t n = d->operand(1), bytes = scalarBytes(d->operand(0));
      *size = bytes * n;
      *align = bytes * (n == 2 ? 2 : 4);
      return;
    }
    case spv::OpTypeMatrix: {
      const Instruction* column = m.definition(d->operand(0));
      const uint32_t bytes = column ? scalarBytes(column->operand(0)) : 4;
      const uint32_t rows = column ? column->operand(1) : 4;
      *matrixStride = std::max(bytes * (rows == 2 ? 2 : 4), 16u);
      *size = *matrixStride * d->operand(1);
      *align = *matrixStride;
      return;
    }
    case spv::OpTypeArray: {
      uint32_t element = d->operand(0), length = d->operand(1);
      uint32_t elementSize, elementAlign;
      std140(m, &element, &elementSize, &elementAlign, matrixStride);
      uint32_t stride = (std::max({elementSize, elementAlign, 16u}) + 15) & ~15u;
      const Instruction* count = m.definition(length);
      uint32_t id = m.newArrayType(element, length);
      m.decorate(id, spv::DecorationArrayStride, {stride});
      *type = id;
      *size = stride * (count ? count->operand(0) : 1);
      *align = std::max(elementAlign, 16u);
      return;
    }
    default:
      *size = 16; *align = 16; return;
  }
}

// gl_VertexID / gl_InstanceID become Vulkan's VertexIndex / InstanceIndex. True when one was there.
bool renameVertexBuiltIns(spirv::Module& m) {
  bool changed = false;
  for (auto& inst : m.annotations)
    if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationBuiltIn)) {
      if (inst.operand(2) == uint32_t(spv::BuiltInVertexId)) inst.operands[2] = spv::BuiltInVertexIndex, changed = true;
      if (inst.operand(2) == uint32_t(spv::BuiltInInstanceId)) inst.operands[2] = spv::BuiltInInstanceIndex, changed = true;
    }
  return changed;
}

// The loose (non-opaque) uniforms, in declaration order, and the highest binding of the others.
std::vector<uint32_t> looseUniforms(const spirv::Module& m, uint32_t* highestBinding, bool* anyBinding) {
  std::vector<uint32_t> loose;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    if (inst.operand(0) == spv::StorageClassUniformConstant && !m.isOpaqueType(m.pointeeType(inst.typeId))) {
      loose.push_back(inst.resultId);  // its auto-mapped binding goes away with it
      continue;
    }
    if (auto b = m.decorationValue(inst.resultId, spv::DecorationBinding)) {
      *highestBinding = *anyBinding ? std::max(*highestBinding, *b) : *b;
      *anyBinding = true;
    }
  }
  return loose;
}

// glslang's auto-mapped locations can collide with explicit ones in OpenGL shaders (the GL linker
// would have assigned them); give each collider the next free location, the same way in every copy.
// True when one collided.
bool separateCollidingLocations(spirv::Module& m) {
  bool changed = false;
  for (auto storage : {spv::StorageClassInput, spv::StorageClassOutput}) {
    std::set<uint32_t> used;
    std::vector<uint32_t> colliders;
    uint32_t highest = 0;
    for (const auto& inst : m.typesValues) {
      if (inst.opcode != spv::OpVariable || inst.operand(0) != uint32_t(storage)) continue;
      auto location = m.decorationValue(inst.resultId, spv::DecorationLocation);
      if (!location) continue;
      highest = std::max(highest, *location);
      if (!used.insert(*location).second) colliders.push_back(inst.resultId);
    }
    for (uint32_t var : colliders) {
      m.removeDecorations(var, spv::DecorationLocation);
      m.decorate(var, spv::DecorationLocation, {++highest + 3});  // past any matrix-sized neighbour
      changed = true;
    }
  }
  return changed;
}

// The default uniform block: one member per loose uniform, std140 offsets; its variable in set 0
// (the binding is the caller's). `memberTypes` receives each member's type.
uint32_t defaultUniformBlock(spirv::Module& m, const std::vector<uint32_t>& loose, std::vector<uint32_t>* memberTypes) {
  std::vector<uint32_t> offsets;
  std::vector<uint32_t> matrixStrides;
  uint32_t offset = 0;
  for (uint32_t var : loose) {
    uint32_t type = m.pointeeType(m.definition(var)->typeId), size, align, matrixStride;
    std140(m, &type, &size, &align, &matrixStride);
    offset = (offset + align - 1) / align * align;
    memberTypes->push_back(type);
    offsets.push_back(offset);
    matrixStrides.push_back(matrixStride);
    offset += size;
  }
  uint32_t block = m.newStruct(*memberTypes);
  m.decorate(block, spv::DecorationBlock);
  m.setName(block, "gl_DefaultUniformBlock");
  for (uint32_t i = 0; i < loose.size(); ++i) {
    m.decorateMember(block, i, spv::DecorationOffset, {offsets[i]});
    m.setMemberName(block, i, m.name(loose[i]));
    if (matrixStrides[i]) {
      m.decorateMember(block, i, spv::DecorationColMajor);
      m.decorateMember(block, i, spv::DecorationMatrixStride, {matrixStrides[i]});
    }
  }
  uint32_t blockVar = m.addGlobalVariable(m.typePointer(spv::StorageClassUniform, block), spv::StorageClassUniform);
  m.decorate(blockVar, spv::DecorationDescriptorSet, {0});
  return blockVar;
}

// A load of a bool (or bvecN) the default block stores as an unsigned integer (storedAsUint) loads
// the integer and compares it with 0: the shader gets the bool it read before, true for any nonzero.
void loadStoredBoolsAsBools(spirv::Module& m, const std::set<uint32_t>& uniformPointers) {
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks) {
      std::vector<Instruction> rewritten;
      rewritten.reserve(block.instructions.size());
      for (auto& inst : block.instructions) {
        const bool fromBlock = inst.opcode == spv::OpLoad && uniformPointers.count(inst.operand(0));
        const uint32_t stored = fromBlock ? storedAsUint(m, inst.typeId) : inst.typeId;
        if (stored == inst.typeId) {
          rewritten.push_back(std::move(inst));
          continue;
        }
        spirv::Builder b(m, rewritten);
        const uint32_t loaded = b.load(stored, inst.operand(0));
        b.addAs(inst.resultId, spv::OpINotEqual, inst.typeId, {loaded, nullOf(m, stored)});
      }
      block.instructions = std::move(rewritten);
    }
  m.invalidateDefinitions();
}

// Every use of a loose uniform becomes a chain into the block, made at the top of the function;
// chains built on those pointers point into Uniform storage then.
void readLooseUniformsFromBlock(spirv::Module& m, const std::vector<uint32_t>& loose,
                                const std::vector<uint32_t>& memberTypes, uint32_t blockVar) {
  std::map<uint32_t, uint32_t> memberOf;
  for (uint32_t i = 0; i < loose.size(); ++i) memberOf[loose[i]] = i;
  std::set<uint32_t> uniformPointers;
  for (auto& fn : m.functions) {
    if (fn.blocks.empty()) continue;
    std::map<uint32_t, uint32_t> replacement;
    std::vector<Instruction> chains;
    for (auto& block : fn.blocks)
      for (auto& inst : block.instructions)
        for (size_t k = 0; k < inst.operands.size(); ++k) {
          // Only value operands: a literal (an extended instruction number such as GLSL.std.450
          // Normalize = 69) may equal a uniform's id by chance.
          if (!spirv::isValueOperand(inst, k)) continue;
          uint32_t& operand = inst.operands[k];
          auto it = memberOf.find(operand);
          if (it == memberOf.end()) continue;
          if (!replacement.count(operand)) {
            spirv::Builder b(m, chains);
            uint32_t id = b.reserveId();
            uint32_t pointee = memberTypes[it->second];
            b.addAs(id, spv::OpAccessChain, m.typePointer(spv::StorageClassUniform, pointee),
                    {blockVar, m.constantInt(static_cast<int32_t>(it->second))});
            replacement[operand] = id;
            uniformPointers.insert(id);
          }
          operand = replacement[operand];
        }
    auto& first = fn.blocks.front().instructions;
    size_t at = 0;
    while (at < first.size() && first[at].opcode == spv::OpVariable) ++at;
    first.insert(first.begin() + static_cast<long>(at), chains.begin(), chains.end());
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (auto& fn : m.functions)
      for (auto& block : fn.blocks)
        for (auto& inst : block.instructions)
          if ((inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain) &&
              uniformPointers.count(inst.operand(0)) && !uniformPointers.count(inst.resultId)) {
            inst.typeId = m.typePointer(spv::StorageClassUniform, storedAsUint(m, m.pointeeType(inst.typeId)));
            uniformPointers.insert(inst.resultId);
            grew = true;
          }
  }
  loadStoredBoolsAsBools(m, uniformPointers);
}

// Drops the loose variables and everything that names them.
void dropVariables(spirv::Module& m, const std::vector<uint32_t>& variables) {
  std::set<uint32_t> gone(variables.begin(), variables.end());
  std::erase_if(m.typesValues, [&](const Instruction& i) { return gone.count(i.resultId) > 0; });
  m.forgetIds(gone);
  for (auto& entry : m.entryPoints)
    std::erase_if(entry.operands, [&](uint32_t id) { return gone.count(id) > 0; });
  m.invalidateDefinitions();
}

}  // namespace

bool convertOpenGLForVulkan(spirv::Module& m, uint32_t blockBinding, std::string* error) {
  bool changed = renameVertexBuiltIns(m);
  uint32_t highestBinding = 0;
  bool anyBinding = false;
  const std::vector<uint32_t> loose = looseUniforms(m, &highestBinding, &anyBinding);
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassUniformConstant)
      m.removeDecorations(inst.resultId, spv::DecorationLocation);
  changed |= separateCollidingLocations(m);
  if (loose.empty()) return changed;

  std::vector<uint32_t> memberTypes;
  uint32_t blockVar = defaultUniformBlock(m, loose, &memberTypes);
  if (anyBinding && highestBinding >= blockBinding) {
    *error = "binding " + std::to_string(blockBinding) + " for the default uniform block is taken";
    return false;
  }
  m.decorate(blockVar, spv::DecorationBinding, {blockBinding});
  readLooseUniformsFromBlock(m, loose, memberTypes, blockVar);
  dropVariables(m, loose);
  return true;
}

}  // namespace stereoshift::harness
