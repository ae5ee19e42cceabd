// The command line's own usage errors in the house format: CLI11's parse errors reported as
// "stereoshift: error: ..." with the error summary, an unknown option naming the nearest known one
// ("did you mean"), a bad or missing value naming what the option takes.
#pragma once

#include "cli/cli11_fwd.h"

#include <cstddef>
#include <ostream>
#include <string>

namespace stereoshift {

// Reports one of CLI11's own parse errors: an unknown option names the nearest known one, an option
// with a value outside its set lists the set. --help and --version are handed back to CLI11.
// Returns the exit status (2, a usage error, like the CLI's other option errors).
int reportParseError(const CLI::App& app, const CLI::ParseError& error, std::ostream& log);
// Edit distance (insertions, deletions, substitutions and adjacent transpositions) of two strings.
size_t editDistance(const std::string& a, const std::string& b);

}  // namespace stereoshift
