// stereoshift public API: turn one mono shader (or one pipeline of stages) into its stereo version.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "transpiler/transpile_options.h"
#include "transpiler/report.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

struct TranspileResult {
  bool ok = false;
  bool changed = false;          // some pass changed the shader
  bool copiedThrough = false;    // output is the input's bytes (nothing to do)
  std::string output;            // text, or the bytes of a SPIR-V binary
  bool binaryOutput = false;
  Diagnostics diagnostics;
  SourceInfo source;             // what the front end found about the input
  StageRecord record;            // what the driver decided and what each part did (typed)
  nlohmann::json report;         // the record rendered (renderStageReport), for --report and build
  std::vector<std::string> includedFiles;
  std::string passLog;           // --print-all output
  std::vector<uint32_t> originalSpirv;  // the input as the front end made it, before any pass
};

// What an input is, decided once per input (here only): its way through the driver follows from it.
enum class InputKind {
  Source,       // GLSL, HLSL or SPIR-V: the front end, the passes, a back-end route
  D3DAssembly,  // D3D shader assembly (a 3Dmigoto dump): the assembly reader, no front end or SPIR-V
};
InputKind decideInputKind(const SourceFile& input);

// Converts one shader.
TranspileResult transpile(const SourceFile& input, const TranspileOptions& options);

// Converts the stages of one pipeline: only the last pre-rasterization stage is shifted.
std::vector<TranspileResult> transpilePipeline(const std::vector<SourceFile>& stages,
                                               const TranspileOptions& options);

// The output file extension a conversion writes by default (the input's, or the target language's).
std::string defaultOutputExtension(const SourceFile& input, const TranspileOptions& options);

const char* version();

}  // namespace stereoshift
