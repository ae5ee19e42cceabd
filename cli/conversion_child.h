// The forked child of the single-shader command: it reads and converts the shaders and writes
// nothing; the parent gets back what it would write (a ConversionRun, through the result codec).
// A crash in the front end (glslang overflows its stack on some inputs) or a conversion past the
// time limit becomes a clear error instead of a core dump or a hang.
#pragma once

#include "cli/conversion_options.h"
#include "cli/result_codec.h"

#include <functional>
#include <string>
#include <vector>

namespace stereoshift {

// Converts `paths` in a forked child (in this process with STEREOSHIFT_NO_FORK=1, for a debugger:
// no time limit then) and hands back its run. False when the child did not answer — it crashed,
// ran past o.timeoutSeconds or answered garbage —, the error and its summary already printed.
bool runConversionChild(const CliOptions& o, const std::vector<std::string>& paths,
                        const std::function<std::string(size_t)>& outputFor, ConversionRun* run);

}  // namespace stereoshift
