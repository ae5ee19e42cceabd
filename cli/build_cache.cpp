// The incremental cache of `stereoshift build`: job keys, loading and saving the cache, the
// integrity of the outputs it lists, and the removal of stale outputs.
#include "cli/build_cache.h"

#include "cli/build_report.h"
#include "cli/cli_support.h"
#include "transpiler/source/file_io.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

constexpr int kCacheFormat = 3;  // 3: reports kept as report text

std::string hex64(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// Feeds length-prefixed strings into one hash, so ("ab","c") and ("a","bc") differ.
class KeyHasher {
 public:
  KeyHasher() { XXH3_64bits_reset(&state_); }
  void add(const std::string& s) {
    uint64_t size = s.size();
    XXH3_64bits_update(&state_, &size, sizeof size);
    XXH3_64bits_update(&state_, s.data(), s.size());
  }
  std::string digest() { return hex64(XXH3_64bits_digest(&state_)); }

 private:
  XXH3_state_t state_;
};

// The names of every file under the include roots of a job, as one hash: a failure for want of an
// #include resolves once the file appears, so a cached failure must notice new files there. One
// listing per root and run (the parent runs one build); the output directory is not listed.
std::string includeRootsDigest(const BuildJob& job, const fs::path& outDir) {
  static std::map<std::string, std::string> digestOfRoot;
  std::error_code ec;
  const fs::path outCanonical = fs::weakly_canonical(outDir, ec);
  KeyHasher h;
  for (const auto& root : job.options.includeDirs) {
    auto [at, fresh] = digestOfRoot.try_emplace(root);
    if (fresh) {
      std::vector<std::string> names;
      std::vector<fs::path> pending = {root};
      while (!pending.empty()) {
        fs::path dir = std::move(pending.back());
        pending.pop_back();
        for (fs::directory_iterator it(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
          std::error_code entryError;
          names.push_back(it->path().lexically_relative(root).generic_string());
          if (it->is_directory(entryError) && !it->is_symlink(entryError) &&
              fs::weakly_canonical(it->path(), entryError) != outCanonical)
            pending.push_back(it->path());
        }
      }
      std::sort(names.begin(), names.end());
      KeyHasher listing;
      for (const auto& name : names) listing.add(name);
      at->second = listing.digest();
    }
    h.add(root);
    h.add(at->second);
  }
  return h.digest();
}

// Whether the output at `path` still holds the bytes of `hash`. Its stamp answers without reading
// it when it is the one recorded and that one was taken after the file last changed: the status-
// change time has the clock's granularity, so a change in the same tick as the cache was written
// would leave the stamp as it was; such a stamp is not trusted (as git treats "racily clean" files).
bool outputIntact(const std::string& path, const nlohmann::json& hash, const nlohmann::json* recorded,
                  std::int64_t savedAtNs) {
  if (recorded && recorded->is_array() && recorded->size() == 4 && (*recorded)[3].is_number_integer() &&
      (*recorded)[3].get<std::int64_t>() < savedAtNs && *recorded == fileStamp(path))
    return true;
  std::string bytes;
  return hash.is_string() && readFile(path, &bytes) && hashBytes(bytes) == hash.get_ref<const std::string&>();
}

// Whether the cached entry still describes the outputs on disk, byte for byte.
bool outputsIntact(const nlohmann::json& entry, std::int64_t savedAtNs) {
  auto outputs = entry.find("outputs");
  if (outputs == entry.end() || !outputs->is_object()) return false;
  auto stamps = entry.find("output_stamps");
  const bool stamped = stamps != entry.end() && stamps->is_object();
  for (const auto& [path, hash] : outputs->items()) {
    const nlohmann::json* recorded = nullptr;
    if (stamped)
      if (auto at = stamps->find(path); at != stamps->end()) recorded = &*at;
    if (!outputIntact(path, hash, recorded, savedAtNs)) return false;
  }
  return true;
}

// The include list of a cached entry (see JobResult::outputIncludes); false when it has none.
bool cachedOutputIncludes(const nlohmann::json& entry, JobResult* result) {
  auto includes = entry.find("output_includes");
  if (includes == entry.end() || !includes->is_array()) return false;
  for (const auto& file : *includes)
    if (!file.is_string()) return false;
  result->outputIncludes = includes->get<std::vector<std::string>>();
  result->outputIncludesKnown = true;
  return true;
}

// The reports of a cached entry, as text marked up to date, and their facts; false when the entry
// does not hold them in the expected form (then the pipeline converts again).
bool cachedReports(const nlohmann::json& entry, JobResult* result) {
  auto texts = entry.find("report_texts");
  auto facts = entry.find("report_facts");
  if (texts == entry.end() || facts == entry.end() || !texts->is_array() || !facts->is_array() ||
      texts->size() != facts->size())
    return false;
  std::vector<std::string> marked;
  std::vector<std::pair<bool, std::string>> counted;
  for (size_t k = 0; k < texts->size(); ++k) {
    const auto& text = (*texts)[k];
    const auto& fact = (*facts)[k];
    if (!text.is_string() || !fact.is_array() || fact.size() != 2 || !fact[0].is_boolean() || !fact[1].is_string())
      return false;
    std::string cachedText;
    if (!markEntryCached(text.get_ref<const std::string&>(), &cachedText)) return false;
    marked.push_back(std::move(cachedText));
    counted.emplace_back(fact[0].get<bool>(), fact[1].get<std::string>());
  }
  result->reportTexts = std::move(marked);
  result->reportFacts = std::move(counted);
  return true;
}

}  // namespace

std::string hashBytes(const std::string& bytes) { return hex64(XXH3_64bits(bytes.data(), bytes.size())); }

std::string hashFile(const std::string& path) {
  std::string bytes;
  return readFile(path, &bytes) ? hashBytes(bytes) : std::string();
}

FileStamp statStamp(const fs::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return {};
  auto ns = [](const struct timespec& t) { return std::int64_t(t.tv_sec) * 1000000000 + t.tv_nsec; };
  return {std::int64_t(info.st_size), std::uint64_t(info.st_ino), ns(info.st_mtim), ns(info.st_ctim)};
}

nlohmann::json fileStamp(const fs::path& path) {
  const FileStamp s = statStamp(path);
  if (s.size < 0) return nullptr;
  return {s.size, s.inode, s.modifiedNs, s.changedNs};
}

std::string toolIdentity() {
  std::string id = std::string("stereoshift ") + version();
  struct stat info {};
  if (::stat("/proc/self/exe", &info) == 0)
    id += " " + std::to_string(info.st_size) + " " + std::to_string(info.st_mtim.tv_sec) + "." +
          std::to_string(info.st_mtim.tv_nsec);
  return id;
}

std::string jobKey(const std::string& tool, const BuildJob& job, const std::vector<std::string>& dependencies,
                   const FileDigest& digestOf) {
  KeyHasher h;
  h.add(tool);
  h.add(job.fingerprint);
  auto addFile = [&](const std::string& path) {
    const std::string digest = digestOf(path);
    h.add(path);
    h.add(digest.empty() ? std::string("<missing>") : "=" + digest);
  };
  for (const auto& stage : job.stages) addFile(stage.string());
  for (const auto& o : job.outputs) h.add(o.string());
  for (const auto& d : dependencies) addFile(d);
  return h.digest();
}

Cache loadCache(const fs::path& file) {
  Cache cache;
  std::string bytes;
  if (!readFile(file.string(), &bytes)) return cache;
  nlohmann::json j = nlohmann::json::from_msgpack(bytes, true, false);  // a damaged cache is no cache
  if (j.is_discarded() || !j.is_object() || j.value("format", 0) != kCacheFormat) return cache;
  if (j.contains("jobs") && j["jobs"].is_object()) cache.jobs = std::move(j["jobs"]);
  const nlohmann::json saved = fileStamp(file);
  if (saved.is_array()) cache.savedAtNs = saved[3].get<std::int64_t>();
  return cache;
}

void saveCache(const fs::path& file, const std::string& tool, Cache&& next) {
  nlohmann::json cacheJson = {{"format", kCacheFormat}, {"tool", tool}, {"jobs", std::move(next.jobs)}};
  std::vector<std::uint8_t> packed = nlohmann::json::to_msgpack(cacheJson);
  if (Status written = writeAtomically(file, std::string(packed.begin(), packed.end())); !written)
    std::cerr << file.string() << ": warning: cannot write the cache (" << written.error().message
              << "); the next run converts everything\n";
}

std::vector<size_t> reuseUpToDate(const Plan& plan, const std::string& tool, bool trusted, Cache& previous,
                                  Cache& next, std::vector<JobResult>& results) {
  std::vector<size_t> toConvert;
  // Each input and included file hashed once: many jobs share a header, and the plan read most.
  std::map<std::string, std::string> digests = plan.fileDigests;
  const FileDigest digestOf = [&](const std::string& path) {
    auto [at, added] = digests.emplace(path, std::string());
    if (added) at->second = hashFile(path);
    return at->second;
  };
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    const BuildJob& job = plan.jobs[i];
    if (!convertsShaders(job.mode)) continue;  // copied through, never cached
    auto entry = trusted ? previous.jobs.find(job.id) : previous.jobs.end();
    if (entry == previous.jobs.end() || !entry->is_object()) {
      toConvert.push_back(i);
      continue;
    }
    std::vector<std::string> dependencies = entry->value("dependencies", std::vector<std::string>{});
    // A failure also depends on what is missing: the files its include roots do not hold yet.
    const auto failed = entry->find("errors");
    const bool isFailure = failed != entry->end() && failed->is_number_integer() && failed->get<int>() > 0;
    if (entry->value("key", "") == jobKey(tool, job, dependencies, digestOf) &&
        outputsIntact(*entry, previous.savedAtNs) &&
        (!isFailure || entry->value("include_roots", "") == includeRootsDigest(job, plan.outputDir)) &&
        cachedReports(*entry, &results[i])) {
      results[i].dependencies = std::move(dependencies);
      cachedOutputIncludes(*entry, &results[i]);
      if (isFailure) {
        results[i].errors = failed->get<int>();
        results[i].log = entry->value("log", "");
      }
      next.jobs[job.id] = std::move(*entry);  // `previous` keeps only what did not carry over
    } else {
      toConvert.push_back(i);
    }
  }
  return toConvert;
}

void recordFinished(Cache& next, const Plan& plan, const BuildJob& job, const JobResult& result,
                    nlohmann::json outputs, nlohmann::json stamps) {
  nlohmann::json texts = nlohmann::json::array(), facts = nlohmann::json::array();
  for (const auto& r : result.reports) {
    texts.push_back(reportEntryText(r));
    auto [ok, classification] = reportFacts(r);
    facts.push_back({ok, classification});
  }
  next.jobs[job.id] = {{"key", result.key},
                       {"dependencies", result.dependencies},
                       {"outputs", std::move(outputs)},
                       {"output_stamps", std::move(stamps)},
                       {"report_texts", std::move(texts)},
                       {"report_facts", std::move(facts)}};
  auto& entry = next.jobs[job.id];
  if (result.outputIncludesKnown) entry["output_includes"] = result.outputIncludes;
  if (result.errors) {
    entry["errors"] = result.errors;
    entry["log"] = result.log;
    entry["include_roots"] = includeRootsDigest(job, plan.outputDir);
  }
}

int removeStaleOutputs(const Plan& plan, const Cache& previous, const fs::path& outDir) {
  int removed = 0;
  std::set<std::string> planned;  // native strings: paths compare component by component
  for (const auto& job : plan.jobs)
    for (const auto& out : job.outputs) planned.insert(out.string());
  std::error_code ec;
  for (const auto& [id, entry] : previous.jobs.items()) {
    if (!entry.is_object()) continue;  // carried over into this run's cache
    const nlohmann::json outputs = entry.value("outputs", nlohmann::json::object());
    if (!outputs.is_object()) continue;
    for (const auto& [path, hash] : outputs.items()) {
      std::string bytes;
      if (!planned.count(path) && hash.is_string() && insideDirectory(path, outDir) &&
          linkOutOfOutputDirectory(fs::path(path).parent_path(), outDir).empty() && readFile(path, &bytes) &&
          hashBytes(bytes) == hash.get<std::string>() && fs::remove(path, ec))
        ++removed;
    }
  }
  return removed;
}

Status writeIfChanged(const fs::path& outDir, const fs::path& path, const std::string& bytes) {
  if (std::string escape = linkOutOfOutputDirectory(path, outDir); !escape.empty()) return plainError(escape);
  return writeUnlessHolding(path, bytes);
}

}  // namespace stereoshift
