// The incremental cache of `stereoshift build`: what makes a job up to date. A job whose key (tool,
// options, every input and included file) matches the cache and whose outputs are still the bytes
// it wrote runs no conversion: its report entries are replayed, and for a job that failed with
// diagnostics, its messages and error count too (the same inputs fail the same way; a crash or a
// timeout is never cached). Outputs that are gone from the plan (a removed pipeline or stage) are
// removed, but only files this tool wrote and nobody changed since.
#pragma once

#include "cli/build_job.h"
#include "cli/build_plan.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace stereoshift {

// Beside the outputs. MessagePack, not JSON text: a no-op rebuild of a large tree is mostly
// reading this file.
constexpr const char* kCacheFile = ".stereoshift-cache.msgpack";

struct Cache {
  nlohmann::json jobs = nlohmann::json::object();  // id -> {key, dependencies, outputs{path: hash}, reports}
};

// The hash of bytes as the cache keeps it (hex).
std::string hashBytes(const std::string& bytes);

// What a cached result depends on besides its inputs: this very build of the tool.
std::string toolIdentity();

// The key of a job: this tool, its options, and the path and bytes of every input and dependency.
// A file that cannot be read hashes as missing (its reappearance changes the key). `converted`:
// the stages' bytes as the worker converted them (so an edit during the run is not cached as
// converted); otherwise they are read here.
std::string jobKey(const std::string& tool, const BuildJob& job, const std::vector<std::string>& dependencies,
                   const std::vector<SourceFile>* converted = nullptr);

// The cache in `file`; empty when it is missing, damaged or of another format. Entries written by
// another build of the tool are kept (their keys never match: the key holds the tool), for what
// they say about the outputs that tool wrote.
Cache loadCache(const std::filesystem::path& file);
// Writes `next` to `file` (a failure is a warning: the next run converts everything).
void saveCache(const std::filesystem::path& file, const std::string& tool, Cache&& next);

// Fills `results` for every converting job the cache says is up to date and moves its entry from
// `previous` to `next`; returns the indices of the converting jobs that must run (all of them
// unless `trusted`: --no-cache).
std::vector<size_t> reuseUpToDate(const Plan& plan, const std::string& tool, bool trusted, Cache& previous,
                                  Cache& next, std::vector<JobResult>& results);

// Records a job that ran to the end, converted or failed with diagnostics; `outputs` maps each
// output written to its hash.
void recordFinished(Cache& next, const Plan& plan, const BuildJob& job, const JobResult& result,
                    nlohmann::json outputs);

// Deletes the outputs `previous` lists that are no output of the plan (their pipeline, or their
// stage, is gone), when they still hold the bytes this tool wrote; returns how many were deleted.
int removeStaleOutputs(const Plan& plan, const Cache& previous, const std::filesystem::path& outDir);

// Writes `bytes` to the output `path` unless the file already holds them (an unchanged output keeps
// its timestamp, so a build system downstream does not redo its work). Never through a symbolic
// link out of `outDir`: that is an error.
bool writeIfChanged(const std::filesystem::path& outDir, const std::filesystem::path& path, const std::string& bytes,
                    std::string* error);

}  // namespace stereoshift
