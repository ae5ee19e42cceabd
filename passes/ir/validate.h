// SPIR-V validation through SPIRV-Tools, for the environment the source implies (OpenGL GLSL:
// OpenGL 4.5 rules; Vulkan GLSL and HLSL: the oldest Vulkan version that takes the module's SPIR-V
// version; SPIR-V input: the universal environment of
// its own version). Used on the input, after each pass (--validate-each) and before emission.
#pragma once

#include "passes/diagnostics.h"
#include "passes/shader.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

// False, with an "invalid SPIR-V <when>: ..." error in `diags`, when the module does not validate.
bool validateSpirv(const std::vector<uint32_t>& words, const SourceInfo& info, const std::string& file,
                   const std::string& when, Diagnostics& diags);

}  // namespace stereoshift
