// Where a module's buffer device addresses come from, for verify's input synthesis: a shader that
// reads memory through an address (GL_EXT_buffer_reference, HLSL vk::RawBufferLoad) must be given
// addresses of real buffers, or the draw reads wild memory and takes the process down. Pointer-typed
// block members are plain to see in the types; an address held as an integer (uint64_t, uvec2) and
// cast in the code (OpConvertUToPtr, OpBitcast) is found here by following the cast's operand back
// to the block member it was loaded from.
#pragma once

#include "passes/ir/module.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace stereoshift::harness {

struct AddressSources {
  // (struct type, member index) -> the type the address points at: integer members the shader
  // casts to a pointer (every element, for an array member).
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> integerMembers;
  // Set when a cast's operand cannot be followed to a block member (a function parameter, a
  // value from memory reached through another address): the inputs cannot make it valid.
  std::string problem;
};

AddressSources traceAddressSources(const spirv::Module& m);

// Whether `type` is a pointer into PhysicalStorageBuffer memory; *pointee gets what it points at.
bool isDeviceAddressPointer(const spirv::Module& m, uint32_t type, uint32_t* pointee);

}  // namespace stereoshift::harness
