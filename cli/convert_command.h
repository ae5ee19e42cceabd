// The single-shader and --pipeline command: the outputs named, checked against the inputs,
// converted in a forked child (conversion_child.h) and written all or none, with the report and
// the depfile.
#pragma once

#include "cli/conversion_options.h"
#include "cli/output_commit.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace stereoshift {

// Converts one list of stages (a single shader is a pipeline of one). `outputFor(i)` names each
// stage's output; the outputs are appended to `outputs` and nothing is written. Returns the number
// of errors.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o, const std::function<std::string(size_t)>& outputFor,
            nlohmann::json& reports, std::ostream& log, std::vector<PendingOutput>* outputs);

// The single-shader and --pipeline command: converts `paths` (the stages of one pipeline when
// o.pipeline is set) in a forked child, so a crash or a conversion past o.timeoutSeconds costs a
// clear error instead of the tool; writes all outputs or none. Returns the exit status.
int runConvertCommand(const CliOptions& o, const std::vector<std::string>& paths);

}  // namespace stereoshift
