// The check every -o option shares: an explicitly empty path (`-o ''`) is a usage error that names
// the option, not an empty file name in a later write error (or standard output by accident).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace stereoshift {

inline CLI::Validator nonEmptyPath() {
  return CLI::Validator([](std::string& path) { return path.empty() ? std::string("the path is empty") : std::string(); },
                        "");  // no word in the help: the option still reads `-o,--output TEXT`
}

}  // namespace stereoshift
