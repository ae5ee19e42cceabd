// `stereoshift build <src-dir | scene.toml> -o <out-dir>`: converts a whole shader tree.
#pragma once

#include "cli/cli_support.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

struct BuildCommandOptions {
  std::string source;              // a directory, or a scene manifest (.toml)
  std::string output;              // the output directory (mirrors the source tree)
  std::string depfile;             // Makefile-style dependencies of the report
  int jobs = 0;                    // worker processes (0: one per core)
  bool noCache = false;            // convert everything, ignoring the incremental cache
  double jobTimeoutSeconds = 300;  // a pipeline that takes longer is killed and reported
  uint64_t jobMemoryMiB = 4096;    // a worker that maps more is stopped and its pipeline reported (0: none)
  bool dryRun = false;             // list what would be done (converted, up to date, copied); write nothing
  std::string filesFrom;           // --files-from: the tree is the files this lists, not the whole directory
  std::vector<std::string> commandLine;  // as given (the key of a rebuild with nothing changed, build_noop.h)
};

// Registers the build-specific options on the `build` subcommand.
void addBuildOptions(CLI::App& build, BuildCommandOptions& options);

// Runs the conversion; returns the exit status (0: every shader converted or up to date).
int runBuildCommand(const BuildCommandOptions& build, const CliOptions& base);

}  // namespace stereoshift
