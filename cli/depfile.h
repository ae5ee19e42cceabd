// Make/Ninja depfiles (--depfile): the text the single-shader command and `build` write, and its
// parser, which the Bazel action path uses to check what a conversion read against its declared
// inputs. One file, so that the writer and the reader keep to the same escaping rules.
#pragma once

#include "transpiler/stereoshift.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// Make/Ninja depfile text: `target...: dependency...`.
std::string makeDepfile(const std::vector<std::string>& targets, std::vector<std::string> dependencies);

// The depfile of one conversion: the outputs its reports name (output_file) as targets; its sources
// (not standard input) and every file they included as dependencies. nullopt when no report names
// an output (a depfile needs a target).
std::optional<std::string> conversionDepfile(const nlohmann::json& reports, const std::vector<SourceFile>& sources);

// A parsed Makefile-style depfile (the CLI's --depfile): its targets and its dependencies.
struct Depfile {
  std::vector<std::string> targets;
  std::vector<std::string> dependencies;
};
std::optional<Depfile> parseDepfile(const std::string& text);

}  // namespace stereoshift
