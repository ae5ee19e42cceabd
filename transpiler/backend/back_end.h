// Back end: SPIRV-Cross re-emits GLSL / ESSL / HLSL / MSL, then a few targeted repairs make the
// output a drop-in replacement for the input (see README "Back-end routes").
#pragma once

#include "passes/diagnostics.h"
#include "passes/shader.h"

#include <map>
#include <string>
#include <vector>

namespace stereoshift {

// Interface facts read from the SPIR-V before emission (the back end never sees the IR types).
struct EmitHints {
  // HLSL semantic strings (glslang's UserSemantic decorations) by interface location.
  std::map<uint32_t, std::string> inputSemantics, outputSemantics;
  // cbuffer member renames SPIRV-Cross applies: "<instance>_<member>" -> "<member>".
  std::map<std::string, std::string, std::less<>> cbufferMemberNames;
};

struct EmitResult {
  bool ok = false;
  std::string text;
  TargetLanguage language = TargetLanguage::Glsl;  // resolved (never Auto)
  bool vulkanSemantics = false;
};

// Resolves `Auto` to the input's own language.
TargetLanguage resolveTarget(const SourceInfo& info, const TranspileOptions& options);

EmitResult emitSource(const std::vector<uint32_t>& words, const SourceInfo& info, const TranspileOptions& options,
                      const EmitHints& hints, const std::string& file, Diagnostics& diags);

}  // namespace stereoshift
