// The driver's HLSL source-splice step: turns a converted HLSL vertex, geometry or domain shader
// that comes back as HLSL into one stereo file that keeps everything of the input. For a vertex
// shader every other vertex entry point of the file is converted on its own (its own glslang
// compile and passes: a 2D one gets no shift) and spliced in the same text; pixel, hull and
// compute entry points stay as written. `-e NAME` restricts the shift to that entry point. Every
// shifted entry point of the output is re-compiled with glslang. What the text cannot carry of a
// vertex shader leaves it to SPIRV-Cross's re-emit, with a report note saying why.
#pragma once

#include "passes/diagnostics.h"
#include "passes/pass.h"
#include "passes/shader.h"

#include <nlohmann/json.hpp>

#include <string>

namespace stereoshift {

enum class HlslSpliceOutcome {
  NotTaken,  // not this route (or a vertex shader the text cannot carry: the report's note says why)
  Spliced,   // `output` holds the stereo file
  Failed,    // refused or broken: the reason is in `diags`
};

// `context`: the conversion of the file's chosen entry point, after its passes.
HlslSpliceOutcome spliceHlslFile(const SourceFile& input, PassContext& context, TargetLanguage target,
                                 std::string& output, nlohmann::json& report, Diagnostics& diags);

}  // namespace stereoshift
