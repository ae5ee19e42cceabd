// glslang info logs into diagnostics (file:line:col form).
#pragma once

#include "core/diagnostics.h"

#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

// Turns a glslang info log into diagnostics. glslang 12 reports `ERROR: file:line: 'token' : text`
// without a column; the column is recovered by finding the quoted token on that source line.
// `sourceOf(file)` returns the text of a file the compile read (main file or an include).
void parseGlslangLog(const std::string& log, const std::string& mainFile,
                     const std::vector<std::pair<std::string, std::string>>& sources, Diagnostics& out);

}  // namespace stereoshift
