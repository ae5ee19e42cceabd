// See view_vector_flow.h.
#include "passes/analysis/view_vector_flow.h"

#include "passes/analysis/uniform_slots.h"
#include "passes/ir/image_instructions.h"

namespace stereoshift::analysis {

using spirv::Instruction;
using spirv::Module;

namespace {

bool isVariable(const Module& m, uint32_t id) {
  const Instruction* def = m.definition(id);
  return def && def->opcode == spv::OpVariable;
}

// "Varies per vertex / pixel": every value computed from a flagged one is flagged; stores carry
// the flag through function-local and private variables.
struct InputRules final : ValueFlow::ForwardRules {
  explicit InputRules(const Module& m) : m(m) {}
  const Module& m;
  bool storeCarries(const Instruction&, uint32_t root, ValueFlow::Flags) override {
    auto storage = isVariable(m, root) ? m.storageClassOf(root) : std::nullopt;
    return storage == spv::StorageClassFunction || storage == spv::StorageClassPrivate;
  }
  ValueFlow::Flags resultFlags(const Instruction& inst, const ValueFlow::FlagMap& flags) override {
    return inst.opcode == spv::OpVariable ? 0 : ValueFlow::operandFlags(inst, flags);
  }
};

// The view-vector flags: a derived value becomes a direction (normalize, reflect/refract,
// v.xy / v.z) and a tangent-space vector (times a tangent frame); texture coordinates and
// outputs are where it ends.
struct ViewVectorRules final : ValueFlow::ForwardRules {
  ViewVectorRules(ViewVectorFlow& queries, bool throughSamples) : q(queries), throughSamples(throughSamples) {}
  ViewVectorFlow& q;
  bool throughSamples;
  ViewVectorFlow::Sinks sinks;

  bool storeCarries(const Instruction& store, uint32_t root, ValueFlow::Flags f) override {
    if (!isVariable(q.module(), root)) return false;
    if (q.module().storageClassOf(root) != spv::StorageClassOutput) return true;  // a local: its loads carry the value on
    OutputSlot output{root, -1};
    if (q.isInterfaceBlock(root))
      if (auto target = q.valueFlow().resolvePointer(store.operand(0)); target && !target->path.empty() &&
                                                                  target->path.front() != analysis::kAnyIndex)
        output.member = target->path.front();
    sinks.outputs[output] |= static_cast<uint8_t>(f);
    return false;
  }

  ValueFlow::Flags resultFlags(const Instruction& inst, const ValueFlow::FlagMap& flags) override {
    auto flagsOf = [&](uint32_t id) { return static_cast<uint8_t>(ValueFlow::flagsOf(flags, id)); };
    if (spirv::isImageSampleOrFetch(inst.opcode)) {
      uint8_t coordinate = flagsOf(spirv::imageCoordinateOperand(inst));
      sinks.texcoord |= coordinate;
      return throughSamples && coordinate ? kDerived : 0;  // a sampled value is not the view vector any more
    }
    int tainted = 0;
    auto f = static_cast<uint8_t>(ValueFlow::operandFlags(inst, flags, &tainted));
    if (!f) return 0;
    // uv +- f(v): a two-component coordinate moved along a direction (parallax, a POM loop's step;
    // the optimizer folds `uv += a * b` into fma(a, b, uv)). The coordinate moved is per pixel:
    // another addend depends on a stage input. `f(v) * scale + bias` with constant or uniform terms
    // only is a lookup *at* a function of v (an LTC or BRDF table at dot(N, V)), not a move.
    bool addition = inst.opcode == spv::OpFAdd || inst.opcode == spv::OpFSub || isGlslExtInst(q.module(), inst, {GLSLstd450Fma});
    if (addition && vectorSize(inst.typeId) == 2) {
      size_t first = inst.opcode == spv::OpExtInst ? 2 : 0;
      for (size_t k = first; k < inst.operands.size(); ++k) {
        if (!(flagsOf(inst.operands[k]) & kDirection)) continue;
        for (size_t other = first; other < inst.operands.size(); ++other)
          if (other != k && q.dependsOnInput(inst.operands[other])) f |= kOffset;
      }
    }
    if (inst.opcode == spv::OpFSub && tainted == 1 && vectorSize(inst.typeId) >= 3) {
      uint32_t other = flagsOf(inst.operand(0)) ? inst.operand(1) : inst.operand(0);
      if (q.dependsOnInput(other)) sinks.subtractions.insert(inst.resultId);
    }
    if (isGlslExtInst(q.module(), inst, {GLSLstd450Normalize, GLSLstd450Reflect, GLSLstd450Refract})) f |= kDirection;
    // v.xy / v.z: a ratio of two parts of the same vector is a direction's slope.
    if (inst.opcode == spv::OpFDiv && tainted == 2) f |= kDirection;
    if (inst.opcode == spv::OpMatrixTimesVector && flagsOf(inst.operand(1)) && q.isTangentFrame(inst.operand(0)))
      f |= kTangent;
    if (inst.opcode == spv::OpVectorTimesMatrix && flagsOf(inst.operand(0)) && q.isTangentFrame(inst.operand(1)))
      f |= kTangent;
    if (inst.opcode == spv::OpCompositeConstruct && isTangentDots(inst, flagsOf)) f |= kTangent;
    return f;
  }

  uint32_t vectorSize(uint32_t type) const {
    const Instruction* def = q.module().definition(type);
    return def && def->opcode == spv::OpTypeVector ? def->operand(1) : 0;
  }

  // vec3(dot(v, t), dot(v, b), dot(v, n)) with per-vertex t, b, n: tangent space by hand.
  template <class FlagsOf>
  bool isTangentDots(const Instruction& construct, FlagsOf flagsOf) {
    int dots = 0;
    for (uint32_t part : construct.operands) {
      const Instruction* def = q.module().definition(part);
      if (!def || def->opcode != spv::OpDot) continue;
      uint32_t a = def->operand(0), b = def->operand(1);
      if ((flagsOf(a) && q.dependsOnInput(b)) || (flagsOf(b) && q.dependsOnInput(a))) ++dots;
    }
    return dots >= 2;
  }
};

}  // namespace

bool ViewVectorFlow::isInterfaceBlock(uint32_t variable) const {
  const Instruction* var = m_.definition(variable);
  uint32_t type = var ? m_.pointeeType(var->typeId) : 0;
  const Instruction* def = m_.definition(type);
  return def && def->opcode == spv::OpTypeStruct && m_.hasDecoration(type, spv::DecorationBlock);
}

bool ViewVectorFlow::dependsOnInput(uint32_t id) {
  if (!inputDependent_) {
    ValueFlow::FlagMap seeds;
    for (const auto& inst : m_.typesValues)
      if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassInput) seeds[inst.resultId] = kDerived;
    InputRules rules(m_);
    inputDependent_ = flow_.propagate(seeds, rules);
  }
  return !isVariable(m_, id) && ValueFlow::flagsOf(*inputDependent_, id) != 0;
}

bool ViewVectorFlow::isTangentFrame(uint32_t matrix) {
  const Instruction* def = m_.definition(matrix);
  if (!def) return false;
  if (def->opcode == spv::OpTranspose) return isTangentFrame(def->operand(0));
  if (def->opcode == spv::OpCompositeConstruct) {
    const Instruction* type = m_.definition(def->typeId);
    return type && type->opcode == spv::OpTypeMatrix && dependsOnInput(matrix);
  }
  if (def->opcode == spv::OpLoad) {
    uint32_t root = m_.rootVariable(def->operand(0));
    return root && m_.storageClassOf(root) == spv::StorageClassInput;
  }
  return false;
}

ViewVectorFlow::Sinks ViewVectorFlow::follow(const std::map<uint32_t, uint8_t>& seeds, bool throughSamples) {
  ViewVectorRules rules(*this, throughSamples);
  ValueFlow::FlagMap flags = flow_.propagate(ValueFlow::FlagMap(seeds.begin(), seeds.end()), rules);
  for (const auto& [id, f] : flags)
    if (!seeds.count(id)) rules.sinks.anyUse = true;
  return rules.sinks;
}

}  // namespace stereoshift::analysis
