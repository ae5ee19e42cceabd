// The source-splice route of the back end: every HLSL shader that comes back as HLSL and needs the
// shift (vertex, geometry, domain). The original text is kept and the shift the passes decided on
// is spliced into it (hlsl_splice.h), rendered from the same ShiftSpec as the SPIR-V route's shift.
// The Debian SPIRV-Cross cannot emit geometry and domain shaders at all, and what it re-emits of a
// vertex shader is no drop-in (output struct reordered, other entry points dropped). What the text
// cannot carry is refused (geometry, domain) or, for a vertex shader, left to SPIRV-Cross's re-emit
// with a report note saying why; never silently dropped.
#pragma once

#include "passes/diagnostics.h"
#include "passes/pass.h"
#include "passes/shader.h"
#include "transpiler/backend/hlsl_splice.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace stereoshift {

// Whether a shader of `info` emitted as `target` takes the source-splice route.
bool takesSourceSpliceRoute(const SourceInfo& info, TargetLanguage target);

// What of one conversion's pass report (`report["passes"]`) the text cannot carry, in words, or
// empty when the splice renders all of it: any change of a pass besides the classification, the
// cbuffer, the shift and, for a vertex shader, halo copies that are the clip position itself.
std::string spliceBlocker(const nlohmann::json& passes, Stage stage);

// The entry point `name` to shift with the halo copies its passes (`passes`, the report's
// "passes") found, named as the source names them (hlsl_splice.h).
HlslSplicedEntry splicedVertexEntry(const std::string& name, const nlohmann::json& passes);

// Splices the shift into `input` as the passes in `context` set it up (the eye parameters they
// declared, their names and register). `vertexEntries`: vertex shaders only, every entry point of
// the file to shift (the context's own among them); empty: the context's entry point alone. On
// success the stereo HLSL is in `output` and the route and the number of shifted sites are in
// `report`; false with the reason in `diags` when the splice fails or the conversion asks for
// something the text route cannot express; `clash` (optional) then says whether it failed on a
// clash with the source's names or registers rather than on text it does not read.
bool spliceSourceStereo(const SourceFile& input, const PassContext& context,
                        const std::vector<HlslSplicedEntry>& vertexEntries, std::string& output,
                        nlohmann::json& report, Diagnostics& diags, bool* clash = nullptr);

}  // namespace stereoshift
