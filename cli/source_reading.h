// How the CLI reads its input shaders: files, or standard input for the path "-", each that cannot
// be read reported. Where the conversion runs (the forked child, a build worker), never in
// `build`'s parent.
#pragma once

#include "transpiler/stereoshift.h"

#include <ostream>
#include <string>
#include <vector>

namespace stereoshift {

// What diagnostics and reports call a shader read from standard input (the input `-`).
inline constexpr const char* kStdinName = "<stdin>";

// Reads every path into `sources`; each one that cannot be read (or is a directory) is reported to
// `log`. Returns how many failed. The path "-" is standard input, read once; its SourceFile is named
// kStdinName. The test hook (test_hook.h) runs on every path.
int readSources(const std::vector<std::string>& paths, std::vector<SourceFile>* sources, std::ostream& log);
// Why `path` cannot be read, in the words the system uses ("no such file", "Permission denied").
std::string unreadableBecause(const std::string& path);

}  // namespace stereoshift
