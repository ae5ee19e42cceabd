// The plan of `stereoshift build`: turns a source tree (or a scene manifest and the tree it names)
// into the jobs to run, one per pipeline (stages grouped by base name), or one per pass using it
// when a manifest gives a pipeline to several passes (`name.<pass>.vert`).
#pragma once

#include "cli/build_job.h"
#include "cli/cli_support.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace stereoshift {

struct Plan {
  std::filesystem::path root;
  std::filesystem::path outputDir;
  std::vector<BuildJob> jobs;
  std::vector<std::string> errors;    // file:line:col: error: ...
  std::vector<std::string> warnings;
  // Entries of the tree that could not be examined (file: error: ...): reported and counted as
  // errors, but the rest of the tree converts.
  std::vector<std::string> skippedEntries;
  // The manifest and every directory of the tree: a build system that compares timestamps sees a
  // directory change when a shader is added or removed in it, so the step reruns.
  std::vector<std::filesystem::path> extraDependencies;
  // The hash of the bytes of every file the plan read (path as walked -> hashBytes): the up-to-date
  // check keys jobs with them instead of reading each input again.
  std::map<std::string, std::string> fileDigests;
};

// Every pipeline under the directory `root`, converted with `base`. With `only` (build
// --files-from), the tree is those files, not the directory's whole content: paths relative to
// `root`, or absolute ones inside it; one outside it or not a file is an error of the plan.
Plan planDirectory(const std::filesystem::path& root, const std::filesystem::path& outDir, const CliOptions& base,
                   const std::vector<std::filesystem::path>* only = nullptr);
// The pipelines the passes of the manifest use, each with its pass's options.
Plan planManifest(const std::filesystem::path& manifestFile, const std::filesystem::path& outDir,
                  const CliOptions& base);

// The files `text` (the shader, or include file, at `path`) #includes that exist, resolved as the
// front end would (beside `path`, then `userDirs`), canonical; one level, not what those include.
std::vector<std::filesystem::path> includedFiles(const std::filesystem::path& path, const std::string& text,
                                                 const std::vector<std::string>& userDirs);

// Lexically: whether `path` is `directory` or lies under it.
bool insideDirectory(const std::filesystem::path& path, const std::filesystem::path& directory);

// Outputs go only under the output directory, never onto an input, and the output directory is not
// a link into the source tree: the first breach, as an error message, or "".
std::string checkOutputPlacement(const Plan& plan, const std::filesystem::path& outDir);

// Where writing `output` (a path under `outDir`) would follow a symbolic link out of `outDir`
// (the output itself, or a directory on the way to it): why, as a message; "" when it would not.
std::string linkOutOfOutputDirectory(const std::filesystem::path& output, const std::filesystem::path& outDir);

}  // namespace stereoshift
