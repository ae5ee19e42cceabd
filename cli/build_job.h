// What flows between the phases of `stereoshift build`: a job (one pipeline, or one pass's variant
// of it, as the plan made it) and its result (sent back by a worker, or replayed from the cache).
#pragma once

#include "cli/scene_manifest.h"
#include "transpiler/stereoshift.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

struct BuildJob {
  std::string id;                                // pipeline key relative to the root, `@pass` for a variant
  std::vector<std::filesystem::path> stages;     // source files, in path order
  std::vector<std::filesystem::path> outputs;    // one per stage
  std::string pass;                              // manifest pass ("" without a manifest)
  PassMode mode = PassMode::Stereo;
  TranspileOptions options;
  std::string fingerprint;                       // options + mode: part of the cache key
};

struct JobResult {
  int errors = 0;
  std::string log;
  nlohmann::json reports = nlohmann::json::array();
  // Up-to-date jobs: the reports as the run that converted them wrote them, in report text, with
  // what the summary counts of each (ok, classification); `reports` stays empty.
  std::vector<std::string> reportTexts;
  std::vector<std::pair<bool, std::string>> reportFacts;
  std::vector<std::string> outputs;  // per stage; only for stages whose report says ok
  std::vector<std::string> dependencies;
  std::string key;  // the cache key of what was converted
  // The files the outputs on disk #include (includedFiles, canonical), when known without reading
  // them: from the texts just written, or from the cache for an up-to-date job.
  bool outputIncludesKnown = false;
  std::vector<std::string> outputIncludes;
  // Whether the same tool, options and input bytes would fail the same way (diagnostics): such a
  // failure is cached like a success. Not when an input could not be read.
  bool replayable = true;
};

}  // namespace stereoshift
