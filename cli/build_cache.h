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

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace stereoshift {

// Beside the outputs. MessagePack, not JSON text: a no-op rebuild of a large tree is mostly
// reading this file.
constexpr const char* kCacheFile = ".stereoshift-cache.msgpack";

struct Cache {
  // id -> {key, dependencies, outputs{path: hash}, output_stamps{path: stamp}, output_includes, reports}
  nlohmann::json jobs = nlohmann::json::object();
  // When the cache file was written (its status-change time, ns): an output whose stamp says it last
  // changed before that, and still has that stamp, holds the bytes hashed then without being read.
  std::int64_t savedAtNs = 0;
};

// The hash of bytes as the cache keeps it (hex).
std::string hashBytes(const std::string& bytes);
// The hash of a file's bytes, "" when it cannot be read.
std::string hashFile(const std::string& path);

// The hash of a file's bytes by path, for job keys: "" when the file cannot be read.
using FileDigest = std::function<std::string(const std::string& path)>;

// What the file system says about an output: size, inode, modification and status-change times
// (ns), as a JSON array; null when it cannot be read. The status-change time moves with every
// write and cannot be set back, so an unchanged stamp means unchanged bytes, except within the
// clock's granularity of the moment the stamp was taken (see outputIntact in build_cache.cpp).
nlohmann::json fileStamp(const std::filesystem::path& path);
// The same as a value: size -1 when the file cannot be examined.
struct FileStamp {
  std::int64_t size = -1;
  std::uint64_t inode = 0;
  std::int64_t modifiedNs = 0, changedNs = 0;
  bool operator==(const FileStamp&) const = default;
};
FileStamp statStamp(const std::filesystem::path& path);

// What a cached result depends on besides its inputs: this very build of the tool.
std::string toolIdentity();

// The key of a job: this tool, its options, and the path and the hash of the bytes of every input
// and dependency (`digestOf`). A file that cannot be read hashes as missing (its reappearance
// changes the key). The worker passes the hashes of the bytes it converted (so an edit during the
// run is not cached as converted); the up-to-date check those of the bytes the plan read.
std::string jobKey(const std::string& tool, const BuildJob& job, const std::vector<std::string>& dependencies,
                   const FileDigest& digestOf);

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
// output written to its hash, `stamps` to its fileStamp.
void recordFinished(Cache& next, const Plan& plan, const BuildJob& job, const JobResult& result,
                    nlohmann::json outputs, nlohmann::json stamps);

// Deletes the outputs `previous` lists that are no output of the plan (their pipeline, or their
// stage, is gone), when they still hold the bytes this tool wrote; returns how many were deleted.
int removeStaleOutputs(const Plan& plan, const Cache& previous, const std::filesystem::path& outDir);

// Writes `bytes` to the output `path` unless the file already holds them (an unchanged output keeps
// its timestamp, so a build system downstream does not redo its work). Never through a symbolic
// link out of `outDir`: that is an error.
Status writeIfChanged(const std::filesystem::path& outDir, const std::filesystem::path& path, const std::string& bytes);

}  // namespace stereoshift
