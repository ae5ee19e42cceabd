// SPIRV-Cross re-emits GLSL / ESSL / HLSL / MSL, then a few targeted repairs make the output a
// drop-in replacement for the input (docs/architecture.md, "Back-end routes"); the re-emit route
// (reemit_route.h) calls it.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "passes/pass_options.h"
#include "transpiler/backend/back_end_options.h"
#include "transpiler/backend/route.h"

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

struct EmittedSource {
  bool ok = false;
  std::string text;
  TargetLanguage language = TargetLanguage::Glsl;  // resolved (never Auto)
  bool vulkanSemantics = false;
};

// SPIRV-Cross's text of `words` in the target language the options ask for (route.h resolves it).
EmittedSource emitSource(const std::vector<uint32_t>& words, const SourceInfo& info, const BackEndOptions& options,
                         EyeSelect eyeSelect,
                      const EmitHints& hints, const std::string& file, Diagnostics& diags);

}  // namespace stereoshift
