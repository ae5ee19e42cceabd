// This turns the integer-to-pointer casts of a module into the block members that hold the
// addresses (see address_inputs.h).
#include "transpiler/verify/address_inputs.h"

#include <set>
#include <vector>

namespace stereoshift::harness {

using spirv::Instruction;
using spirv::Module;

bool isDeviceAddressPointer(const Module& m, uint32_t type, uint32_t* pointee) {
  const Instruction* d = m.definition(type);
  if (!d || d->opcode != spv::OpTypePointer || d->operand(0) != spv::StorageClassPhysicalStorageBuffer) return false;
  if (pointee) *pointee = d->operand(1);
  return true;
}

namespace {

class AddressTracer {
 public:
  explicit AddressTracer(const Module& m) : m_(m) {
    for (const auto& f : m.functions)
      for (const auto& b : f.blocks)
        for (const auto& inst : b.instructions)
          if (inst.opcode == spv::OpStore) stores_.emplace(inst.operand(0), inst.operand(1));
  }

  void run(AddressSources* out) {
    for (const auto& f : m_.functions)
      for (const auto& b : f.blocks)
        for (const auto& inst : b.instructions) {
          uint32_t pointee = 0;
          const bool cast = inst.opcode == spv::OpConvertUToPtr || inst.opcode == spv::OpBitcast;
          if (!cast || !isDeviceAddressPointer(m_, inst.typeId, &pointee)) continue;
          visited_.clear();
          if (!traceValue(inst.operand(0), pointee, out) && out->problem.empty())
            out->problem = "an address cast to a pointer (%" + std::to_string(inst.resultId) +
                           ") comes from no uniform, storage or push-constant block member the inputs can fill";
        }
  }

 private:
  // Follows an integer value to the block member it was loaded from.
  bool traceValue(uint32_t id, uint32_t pointee, AddressSources* out) {
    if (!visited_.insert(id).second) return false;
    const Instruction* d = m_.definition(id);
    if (!d) return false;
    switch (d->opcode) {
      case spv::OpIAdd:
      case spv::OpISub:  // an offset added to a base address: the base is the input
        return traceValue(d->operand(0), pointee, out) || traceValue(d->operand(1), pointee, out);
      case spv::OpUConvert:
      case spv::OpSConvert:
      case spv::OpBitcast:
      case spv::OpCopyObject:
        return traceValue(d->operand(0), pointee, out);
      case spv::OpLoad:
        return tracePointer(d->operand(0), pointee, out);
      default:
        return false;  // a constant, a parameter, arithmetic the trace does not follow
    }
  }

  // Follows a pointer to a block member (through function-local copies).
  bool tracePointer(uint32_t pointer, uint32_t pointee, AddressSources* out) {
    const Instruction* d = m_.definition(pointer);
    if (!d) return false;
    if (d->opcode == spv::OpVariable) {
      const auto storage = static_cast<spv::StorageClass>(d->operand(0));
      if (storage == spv::StorageClassFunction || storage == spv::StorageClassPrivate) {
        auto stored = stores_.find(pointer);
        return stored != stores_.end() && traceValue(stored->second, pointee, out);
      }
      return false;  // a whole block loaded as one integer: not a form any front end writes
    }
    if (d->opcode != spv::OpAccessChain && d->opcode != spv::OpInBoundsAccessChain) return false;
    const Instruction* base = m_.definition(d->operand(0));
    if (!base || base->opcode != spv::OpVariable) return false;
    const auto storage = static_cast<spv::StorageClass>(base->operand(0));
    if (storage != spv::StorageClassUniform && storage != spv::StorageClassStorageBuffer &&
        storage != spv::StorageClassPushConstant)
      return false;
    uint32_t type = m_.pointeeType(base->typeId);
    std::pair<uint32_t, uint32_t> member{0, 0};
    for (size_t i = 1; i < d->operands.size(); ++i) {
      const Instruction* t = m_.definition(type);
      if (!t) return false;
      if (t->opcode == spv::OpTypeStruct) {
        const Instruction* index = m_.definition(d->operands[i]);
        if (!index || index->opcode != spv::OpConstant || index->operand(0) >= t->operands.size()) return false;
        member = {type, index->operand(0)};
        type = t->operands[index->operand(0)];
      } else if (t->opcode == spv::OpTypeArray || t->opcode == spv::OpTypeRuntimeArray) {
        type = t->operand(0);
      } else {
        break;  // a component of a uvec2 address: the member holds it
      }
    }
    if (member.first == 0) return false;
    out->integerMembers[member] = pointee;
    return true;
  }

  const Module& m_;
  std::multimap<uint32_t, uint32_t> stores_;  // variable -> value stored
  std::set<uint32_t> visited_;
};

}  // namespace

AddressSources traceAddressSources(const Module& m) {
  AddressSources out;
  if (!m.hasCapability(spv::CapabilityPhysicalStorageBufferAddresses)) return out;
  AddressTracer(m).run(&out);
  return out;
}

}  // namespace stereoshift::harness
