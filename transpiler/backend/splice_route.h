// The source-splice route of the back end: HLSL geometry and domain shaders that come back as
// HLSL. The Debian SPIRV-Cross cannot emit those stages, so the original text is kept and the
// shift the passes decided on is spliced into it (hlsl_splice.h), rendered from the same ShiftSpec
// as the SPIR-V route's shift. What the text cannot carry is refused, never silently dropped.
#pragma once

#include "passes/diagnostics.h"
#include "passes/pass.h"
#include "passes/shader.h"

#include <nlohmann/json.hpp>

#include <string>

namespace stereoshift {

// Whether a shader of `info` emitted as `target` takes the source-splice route.
bool takesSourceSpliceRoute(const SourceInfo& info, TargetLanguage target);

// Splices the shift into `input` as the passes in `context` set it up (the eye parameters they
// declared, their names and register). On success the stereo HLSL is in `output` and the route and
// the number of shifted sites are in `report`; false with the reason in `diags` when the splice
// fails or the conversion asks for something the text route cannot express.
bool spliceSourceStereo(const SourceFile& input, const PassContext& context, std::string& output,
                        nlohmann::json& report, Diagnostics& diags);

}  // namespace stereoshift
