// SPIR-V validation through SPIRV-Tools, for the environment the source implies (OpenGL GLSL:
// OpenGL 4.5 rules; Vulkan GLSL and HLSL: the oldest Vulkan version that takes the module's SPIR-V
// version; SPIR-V input: the universal environment of
// its own version). Used on the input, after each pass (--validate-each) and before emission.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

// False, with an "invalid SPIR-V <when>: ..." error in `diags`, when the module does not validate.
//
// glslang makes SPIR-V that the validator refuses from some valid OpenGL GLSL (a loose `uniform bool`
// is a Bool variable in UniformConstant storage, which SPIR-V forbids): the passes must not be blamed
// for what the front end made. With `frontEnd` (the module as glslang made it), an error that the
// front end's module already has, word for word, is inherited: the call succeeds and `*inherited`
// holds it. spirv-val stops at the first error, so a later one of the passes' own would hide behind
// it; the back end refuses to write such a module as SPIR-V.
bool validateSpirv(const std::vector<uint32_t>& words, const SourceInfo& info, const std::string& file,
                   const std::string& when, Diagnostics& diags, const std::vector<uint32_t>* frontEnd = nullptr,
                   std::string* inherited = nullptr);

// The validator's error messages for `words` ("" when they validate).
std::string validationErrors(const std::vector<uint32_t>& words, const SourceInfo& info);

// The errors Vulkan 1.0's strict block layout finds that the relaxed one (VK_KHR_relaxed_block_layout,
// core from Vulkan 1.1) does not: HLSL's cbuffer packing (a float3 right after a float) in a module
// otherwise valid for Vulkan 1.0. "" when there are none.
std::string vulkan10StrictLayoutErrors(const std::vector<uint32_t>& words);

}  // namespace stereoshift
