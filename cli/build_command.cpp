// `stereoshift build`: a whole shader tree (or the pipelines a scene manifest names) converted
// incrementally, in isolated worker processes, into a mirrored output directory.
//
// The run, in order:
//  1. plan: find the shaders, group stages into pipelines by base name, and (with a manifest) give
//     each pipeline the passes that use it; a pipeline used by several passes becomes one variant
//     per pass (`name.<pass>.vert`).
//  2. cache: a job whose key (tool, options, every input and included file) matches the cache and
//     whose outputs are still the bytes it wrote is up to date: nothing runs for it.
//  3. convert the rest in worker processes (a crash or a hang costs one pipeline, not the run), and
//     write each output atomically as it arrives.
//  4. report, in path order, whatever the number of workers: logs, the JSON report, the cache, the
//     depfile.
#include "cli/build_command.h"

#include "cli/scene_manifest.h"
#include "cli/worker_pool.h"
#include "transpiler/frontend/front_end.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// MessagePack, not JSON text: a no-op rebuild of a large tree is mostly reading this file.
constexpr const char* kCacheFile = ".stereoshift-cache.msgpack";
constexpr int kCacheFormat = 3;  // 3: reports kept as report text

std::string hex64(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::string hashBytes(const std::string& bytes) { return hex64(XXH3_64bits(bytes.data(), bytes.size())); }

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

// What a cached result depends on besides its inputs: this very build of the tool.
std::string toolIdentity() {
  std::string id = std::string("stereoshift ") + version();
  struct stat info {};
  if (::stat("/proc/self/exe", &info) == 0)
    id += " " + std::to_string(info.st_size) + " " + std::to_string(info.st_mtim.tv_sec) + "." +
          std::to_string(info.st_mtim.tv_nsec);
  return id;
}

// ---- plan ----------------------------------------------------------------------------------------

struct BuildJob {
  std::string id;                 // pipeline key relative to the root, `@pass` for a variant
  std::vector<fs::path> stages;   // source files, in path order
  std::vector<fs::path> outputs;  // one per stage
  std::string pass;               // manifest pass ("" without a manifest)
  PassMode mode = PassMode::Stereo;
  TranspileOptions options;
  std::string fingerprint;        // options + mode: part of the cache key
};

bool insideDirectory(const fs::path& path, const fs::path& directory) {
  fs::path p = path.lexically_normal(), d = directory.lexically_normal();
  auto [end, _] = std::mismatch(d.begin(), d.end(), p.begin(), p.end());
  return end == d.end() || (std::next(end) == d.end() && end->empty());
}

// `dir/name.vert` -> `dir/name.<variant>.vert` (variant before every extension).
fs::path variantPath(const fs::path& path, const std::string& variant) {
  std::string name = path.filename().string();
  size_t dot = name.find('.');
  std::string renamed = dot == std::string::npos ? name + "." + variant
                                                 : name.substr(0, dot) + "." + variant + name.substr(dot);
  return path.parent_path() / renamed;
}

// The conversion-option keys a manifest may set: the CLI long names, less the per-file and
// debugging ones.
std::vector<std::string> manifestOptionKeys() {
  CliOptions scratch;
  CLI::App app;
  addConversionOptions(app, scratch);
  static const std::set<std::string> excluded = {"help", "report", "pass", "print-all", "validate-each", "stage", "D", "I"};
  std::vector<std::string> keys;
  for (const CLI::Option* option : app.get_options())
    for (const auto& name : option->get_lnames())
      if (!excluded.count(name)) keys.push_back(name);
  std::sort(keys.begin(), keys.end());
  return keys;
}

// Applies command-line words (`--block-name X`, `-D A`) on top of `o`; lists (defines, include
// directories) are appended to. Returns an error message or "".
std::string applyOptionWords(CliOptions& o, const std::vector<std::string>& words) {
  if (words.empty()) return "";
  CliOptions updated = o;
  updated.t.defines.clear();
  updated.t.includeDirs.clear();
  CLI::App app;
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  addConversionOptions(app, updated);
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  std::vector<std::string> defines = o.t.defines, includes = o.t.includeDirs;
  defines.insert(defines.end(), updated.t.defines.begin(), updated.t.defines.end());
  includes.insert(includes.end(), updated.t.includeDirs.begin(), updated.t.includeDirs.end());
  updated.t.defines = defines;
  updated.t.includeDirs = includes;
  if (auto error = finishOptions(updated)) return *error;
  o = std::move(updated);
  return "";
}

struct Plan {
  fs::path root;
  std::vector<BuildJob> jobs;
  std::vector<std::string> errors;    // file:line:col: error: ...
  std::vector<std::string> warnings;
  // The manifest and every directory of the tree: a build system that compares timestamps sees a
  // directory change when a shader is added or removed in it, so the step reruns.
  std::vector<fs::path> extraDependencies;
};

// Shader files under `root`, grouped into pipelines keyed by their path relative to `root`; the
// directories walked are appended to `directories`.
std::map<std::string, std::vector<fs::path>> findPipelines(const fs::path& root, const fs::path& outDir,
                                                           std::vector<fs::path>* directories) {
  std::error_code ec;
  std::vector<fs::path> files;
  directories->push_back(root);
  // An output directory inside the source tree is not part of the source.
  fs::path outCanonical = fs::weakly_canonical(outDir, ec);
  for (auto it = fs::recursive_directory_iterator(root, ec); it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    if (it->is_directory()) {
      if (fs::weakly_canonical(it->path(), ec) == outCanonical) {
        it.disable_recursion_pending();
        continue;
      }
      directories->push_back(it->path());
    }
    if (it->is_regular_file() && stageFromPath(it->path().string())) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  std::map<std::string, std::vector<fs::path>> pipelines;
  // Lexical: every file came from walking `root` (fs::relative would resolve both paths per file).
  for (const auto& f : files) pipelines[pipelineKey(f.lexically_relative(root).generic_string())].push_back(f);
  return pipelines;
}

// The options a pass converts with, and their description for the cache key (computed once per
// pass: describing the options per pipeline cost a fifth of a no-op rebuild of a large tree).
struct PassOptions {
  TranspileOptions options;
  std::string fingerprint;  // the options (before per-pipeline include roots) and the mode
};

PassOptions passOptions(const CliOptions& options, PassMode mode) {
  PassOptions p{options.t, ""};
  if (mode == PassMode::Deferred) p.options.deferredUnprojection = true;
  if (mode == PassMode::UiAtDepth) p.options.hudAtDepth = true;
  nlohmann::json fingerprint = describeOptions(p.options);
  fingerprint["mode"] = toString(mode);
  p.fingerprint = fingerprint.dump();
  return p;
}

void addJob(Plan& plan, const fs::path& outDir, const std::string& key, const std::vector<fs::path>& stages,
            const PassOptions& options, const std::string& pass, PassMode mode, bool variant) {
  BuildJob job;
  job.id = variant ? key + "@" + pass : key;
  job.stages = stages;
  job.pass = pass;
  job.mode = mode;
  job.options = options.options;
  job.fingerprint = options.fingerprint;
  // Each shader's directory and an `include` directory beside it are include roots.
  for (const auto& s : stages) {
    fs::path dir = s.parent_path();
    job.options.includeDirs.push_back(dir.string());
    std::error_code ec;
    if (fs::is_directory(dir / "include", ec)) job.options.includeDirs.push_back((dir / "include").string());
  }
  for (size_t i = options.options.includeDirs.size(); i < job.options.includeDirs.size(); ++i)
    job.fingerprint += "\n-I" + job.options.includeDirs[i];
  for (const auto& s : stages) {
    fs::path out = outDir / s.lexically_relative(plan.root);
    if (variant) out = variantPath(out, pass);
    job.outputs.push_back(out);
  }
  plan.jobs.push_back(std::move(job));
}

Plan planDirectory(const fs::path& root, const fs::path& outDir, const CliOptions& base) {
  Plan plan;
  plan.root = root;
  PassOptions options = passOptions(base, PassMode::Stereo);
  for (const auto& [key, stages] : findPipelines(root, outDir, &plan.extraDependencies))
    addJob(plan, outDir, key, stages, options, "", PassMode::Stereo, false);
  return plan;
}

Plan planManifest(const fs::path& manifestFile, const fs::path& outDir, const CliOptions& base) {
  Plan plan;
  plan.extraDependencies.push_back(manifestFile);
  SceneManifest manifest;
  auto check = [](const std::vector<std::string>& words) {
    CliOptions scratch;
    return applyOptionWords(scratch, words);
  };
  if (!loadSceneManifest(manifestFile, manifestOptionKeys(), check, &manifest, &plan.errors)) return plan;
  plan.root = manifest.sourceRoot;
  std::error_code ec;
  if (!fs::is_directory(plan.root, ec)) {
    plan.errors.push_back(manifestFile.string() + ":1:1: error: source directory '" + plan.root.string() +
                          "' does not exist");
    return plan;
  }
  auto pipelines = findPipelines(plan.root, outDir, &plan.extraDependencies);

  CliOptions defaults = base;
  for (const auto& o : manifest.defaults) applyOptionWords(defaults, o.words);  // checked while loading

  // Which passes use each pipeline, in manifest order.
  std::map<std::string, std::vector<const ScenePass*>> users;
  for (const auto& pass : manifest.passes)
    for (const auto& [pattern, where] : pass.pipelines) {
      int matched = 0;
      for (const auto& [key, stages] : pipelines)
        if (pipelineMatches(pattern, key)) {
          auto& list = users[key];
          if (std::find(list.begin(), list.end(), &pass) == list.end()) list.push_back(&pass);
          ++matched;
        }
      if (!matched)
        plan.errors.push_back(manifestFile.string() + ":" + std::to_string(where.line) + ":" +
                              std::to_string(where.column) + ": error: pass '" + pass.name + "': '" + pattern +
                              "' matches no pipeline under " + plan.root.string());
    }
  std::map<const ScenePass*, PassOptions> optionsOf;
  for (const auto& pass : manifest.passes) {
    CliOptions options = defaults;
    for (const auto& o : pass.options) applyOptionWords(options, o.words);
    optionsOf.emplace(&pass, passOptions(options, pass.mode));
  }
  std::vector<std::string> unused;
  for (const auto& [key, stages] : pipelines) {
    auto it = users.find(key);
    if (it == users.end()) {
      unused.push_back(key);
      continue;
    }
    bool variants = it->second.size() > 1;
    for (const ScenePass* pass : it->second) addJob(plan, outDir, key, stages, optionsOf.at(pass), pass->name, pass->mode, variants);
  }
  if (!unused.empty()) {
    std::string list;
    for (size_t i = 0; i < unused.size() && i < 5; ++i) list += (i ? ", " : "") + unused[i];
    if (unused.size() > 5) list += ", ...";
    plan.warnings.push_back(manifestFile.string() + ": warning: " + std::to_string(unused.size()) +
                            " pipeline(s) used by no pass are not emitted: " + list);
  }
  return plan;
}

// The key of a job: this tool, its options, and the path and bytes of every input and dependency.
// A file that cannot be read hashes as missing (its reappearance changes the key). `converted`:
// the stages' bytes as the worker converted them (so an edit during the run is not cached as
// converted); otherwise they are read here.
std::string jobKey(const std::string& tool, const BuildJob& job, const std::vector<std::string>& dependencies,
                   const std::vector<SourceFile>* converted = nullptr) {
  KeyHasher h;
  h.add(tool);
  h.add(job.fingerprint);
  auto addFile = [&](const std::string& path, const std::string* known) {
    std::string bytes;
    h.add(path);
    h.add(known ? "=" + *known : readFile(path, &bytes) ? "=" + bytes : std::string("<missing>"));
  };
  for (size_t i = 0; i < job.stages.size(); ++i)
    addFile(job.stages[i].string(), converted && i < converted->size() ? &(*converted)[i].contents : nullptr);
  for (const auto& o : job.outputs) h.add(o.string());
  for (const auto& d : dependencies) addFile(d, nullptr);
  return h.digest();
}

// ---- what a worker sends back -------------------------------------------------------------------

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
};

void putString(std::string& out, const std::string& s) {
  uint64_t size = s.size();
  out.append(reinterpret_cast<const char*>(&size), sizeof size);
  out += s;
}

bool getString(const std::string& in, size_t& at, std::string* s) {
  uint64_t size;
  if (in.size() - at < sizeof size) return false;
  std::memcpy(&size, in.data() + at, sizeof size);
  at += sizeof size;
  if (in.size() - at < size) return false;
  *s = in.substr(at, size);
  at += size;
  return true;
}

std::string serialize(const JobResult& r) {
  nlohmann::json head = {{"errors", r.errors}, {"log", r.log}, {"reports", r.reports},
                         {"dependencies", r.dependencies}, {"key", r.key}, {"outputs", r.outputs.size()}};
  std::string out;
  putString(out, head.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  for (const auto& o : r.outputs) putString(out, o);
  return out;
}

bool deserialize(const std::string& in, JobResult* r) {
  size_t at = 0;
  std::string text;
  if (!getString(in, at, &text)) return false;
  nlohmann::json head = nlohmann::json::parse(text, nullptr, false);
  if (head.is_discarded()) return false;
  r->errors = head.value("errors", 1);
  r->log = head.value("log", "");
  r->reports = head.value("reports", nlohmann::json::array());
  r->dependencies = head.value("dependencies", std::vector<std::string>{});
  r->key = head.value("key", "");
  size_t count = head.value("outputs", size_t{0});
  r->outputs.resize(count);
  for (auto& o : r->outputs)
    if (!getString(in, at, &o)) return false;
  return true;
}

// Runs in a worker: converts one pipeline, keeping everything in memory.
JobResult convertJob(const BuildJob& job, const std::string& tool) {
  JobResult result;
  std::ostringstream log;
  std::vector<SourceFile> sources;
  std::vector<std::string> paths;
  for (const auto& p : job.stages) paths.push_back(p.string());
  result.errors += readSources(paths, &sources, log);
  if (!result.errors) {
    std::vector<TranspileResult> converted = transpilePipeline(sources, job.options);
    result.outputs.resize(converted.size());
    for (size_t i = 0; i < converted.size(); ++i) {
      auto& r = converted[i];
      int diagnosticErrors = printDiagnostics(r.diagnostics, log);
      if (!r.passLog.empty()) log << r.passLog;
      for (const auto& inc : r.includedFiles) result.dependencies.push_back(inc);
      r.report["ok"] = r.ok;
      if (!job.pass.empty()) {
        r.report["pass"] = job.pass;
        r.report["mode"] = toString(job.mode);
      }
      if (r.ok) {
        result.outputs[i] = std::move(r.output);
        r.report["output_file"] = job.outputs[i].string();
      } else {
        result.errors += std::max(1, diagnosticErrors);
      }
      result.reports.push_back(std::move(r.report));
    }
  }
  std::sort(result.dependencies.begin(), result.dependencies.end());
  result.dependencies.erase(std::unique(result.dependencies.begin(), result.dependencies.end()), result.dependencies.end());
  result.log = log.str();
  result.key = jobKey(tool, job, result.dependencies, &sources);
  return result;
}

// ---- the report ------------------------------------------------------------------------------------

// One shader's entry as it sits in the report's "shaders" array (pretty-printed, indented two levels),
// so entries of up-to-date pipelines are copied from the cache as text instead of rebuilt (a no-op
// rebuild of a tree was mostly reading and writing these).
std::string reportEntryText(const nlohmann::json& report) {
  std::string text = report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace), indented;
  indented.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    indented += c;
    if (c == '\n') indented += "    ";
  }
  return indented;
}

// What the summary counts of a report entry: whether it is ok, and its classification.
std::pair<bool, std::string> reportFacts(const nlohmann::json& report) {
  return {report.value("ok", false), report.value("classification", "?")};
}

// A converted entry starts with "cached": false ("cached" sorts before every other key); an
// up-to-date one says true.
constexpr std::string_view kConvertedPrefix = "{\n      \"cached\": false,";
constexpr std::string_view kCachedPrefix = "{\n      \"cached\": true,";

// ---- the cache ------------------------------------------------------------------------------------

struct Cache {
  nlohmann::json jobs = nlohmann::json::object();  // id -> {key, dependencies, outputs{path: hash}, reports}
};

Cache loadCache(const fs::path& file, const std::string& tool) {
  Cache cache;
  std::string bytes;
  if (!readFile(file.string(), &bytes)) return cache;
  nlohmann::json j = nlohmann::json::from_msgpack(bytes, true, false);  // a damaged cache is no cache
  if (j.is_discarded() || !j.is_object() || j.value("format", 0) != kCacheFormat || j.value("tool", "") != tool)
    return cache;
  if (j.contains("jobs") && j["jobs"].is_object()) cache.jobs = std::move(j["jobs"]);
  return cache;
}


// Whether the cached entry still describes the outputs on disk, byte for byte.
bool outputsIntact(const nlohmann::json& entry) {
  if (!entry.contains("outputs") || !entry["outputs"].is_object()) return false;
  for (const auto& [path, hash] : entry["outputs"].items()) {
    std::string bytes;
    if (!readFile(path, &bytes) || hashBytes(bytes) != hash.get<std::string>()) return false;
  }
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
    const std::string& t = text.get_ref<const std::string&>();
    if (!t.starts_with(kConvertedPrefix)) return false;
    marked.push_back(std::string(kCachedPrefix) + t.substr(kConvertedPrefix.size()));
    counted.emplace_back(fact[0].get<bool>(), fact[1].get<std::string>());
  }
  result->reportTexts = std::move(marked);
  result->reportFacts = std::move(counted);
  return true;
}

// Writes `bytes` unless the file already holds them (an unchanged output keeps its timestamp, so a
// build system downstream does not redo its work).
bool writeIfChanged(const fs::path& path, const std::string& bytes, std::string* error) {
  std::string existing;
  if (readFile(path.string(), &existing) && existing == bytes) return true;
  return writeAtomically(path, bytes, error);
}

// The dialect of a shader, for scheduling: HLSL, SPIR-V, or the GLSL version and profile. Shaders
// of one dialect share glslang's built-in symbol tables inside a worker.
std::string dialectOf(const fs::path& path) {
  std::string name = path.filename().string();
  if (name.ends_with(".hlsl")) return "hlsl";
  if (name.ends_with(".spv")) return "spirv";
  std::string text;
  if (!readFile(path.string(), &text)) return "";
  VersionLine v = findVersion(text);
  return "glsl " + std::to_string(v.version) + (v.es ? " es" : "");
}

void drawProgress(size_t done, size_t total, const std::string& what) {
  constexpr int width = 24;
  int filled = total ? static_cast<int>(width * done / total) : width;
  std::string bar(static_cast<size_t>(filled), '=');
  if (filled < width) bar += '>' + std::string(static_cast<size_t>(width - filled - 1), ' ');
  std::cerr << "\r[" << bar << "] " << done << "/" << total << " " << what << "\x1b[K" << std::flush;
}

}  // namespace

void addBuildOptions(CLI::App& build, BuildCommandOptions& o) {
  build.add_option("source", o.source, "Source directory, or a scene manifest (.toml; see README \"Scene manifest\")")
      ->required();
  build.add_option("-o,--output", o.output, "Output directory (mirrors the source tree)")->required();
  build.add_option("-j,--jobs", o.jobs, "Worker processes (default: one per core); the output does not depend on it");
  build.add_option("--depfile", o.depfile, "Write the dependencies of the report (every input and included file) as a depfile");
  build.add_flag("--no-cache", o.noCache, "Convert every shader, even those the incremental cache says are up to date");
  build.add_option("--job-timeout", o.jobTimeoutSeconds, "Seconds one pipeline may take before it is stopped and reported (0: no limit)")
      ->capture_default_str();
}

int runBuildCommand(const BuildCommandOptions& build, const CliOptions& base) {
  std::error_code ec;
  const fs::path outDir = build.output;
  const bool manifestMode = fs::is_regular_file(build.source, ec);
  if (!manifestMode && !fs::is_directory(build.source, ec)) {
    std::cerr << build.source << ": error: no such directory or manifest\n";
    printErrorSummary(1);
    return 1;
  }
  Plan plan = manifestMode ? planManifest(build.source, outDir, base) : planDirectory(build.source, outDir, base);
  for (const auto& w : plan.warnings) std::cerr << w << "\n";
  if (!plan.errors.empty()) {
    for (const auto& e : plan.errors) std::cerr << e << "\n";
    printErrorSummary(static_cast<int>(plan.errors.size()));
    return 1;
  }
  // Outputs go only under the output directory, and never onto an input. Resolved paths: each
  // directory once, then a file's own name unless the file itself is a symbolic link.
  // (Native strings as keys: std::filesystem::path compares component by component.)
  std::map<std::string, fs::path> resolvedDirectories;
  auto resolved = [&](const fs::path& file) {
    if (fs::is_symlink(file, ec)) return fs::weakly_canonical(file, ec).native();
    fs::path parent = file.parent_path();
    auto [at, fresh] = resolvedDirectories.try_emplace(parent.native());
    if (fresh) at->second = fs::weakly_canonical(parent.empty() ? fs::path(".") : parent, ec);
    return (at->second / file.filename()).native();
  };
  std::set<std::string> inputs;
  for (const auto& job : plan.jobs)
    for (const auto& s : job.stages) inputs.insert(resolved(s));
  for (const auto& job : plan.jobs)
    for (const auto& out : job.outputs)
      if (!insideDirectory(out, outDir) || inputs.count(resolved(out))) {
        std::cerr << out.string() << ": error: output would be outside the output directory or overwrite an input\n";
        printErrorSummary(1);
        return 1;
      }

  const std::string tool = toolIdentity();
  const fs::path cacheFile = outDir / kCacheFile;
  Cache previous = build.noCache ? Cache{} : loadCache(cacheFile, tool);
  Cache next;

  const size_t count = plan.jobs.size();
  std::vector<JobResult> results(count);
  std::vector<size_t> toConvert;
  for (size_t i = 0; i < count; ++i) {
    const BuildJob& job = plan.jobs[i];
    if (!convertsShaders(job.mode)) continue;  // copied in the parent below
    auto entry = previous.jobs.find(job.id);
    if (entry == previous.jobs.end()) {
      toConvert.push_back(i);
      continue;
    }
    std::vector<std::string> dependencies = entry->value("dependencies", std::vector<std::string>{});
    if (entry->value("key", "") == jobKey(tool, job, dependencies) && outputsIntact(*entry) &&
        cachedReports(*entry, &results[i])) {
      results[i].dependencies = std::move(dependencies);
      next.jobs[job.id] = std::move(*entry);  // `previous` keeps only what did not carry over
    } else {
      toConvert.push_back(i);
    }
  }

  // Copy-through passes (mono, post, UI): the bytes of the source, no front end.
  int errors = 0;
  for (size_t i = 0; i < count; ++i) {
    const BuildJob& job = plan.jobs[i];
    if (convertsShaders(job.mode)) continue;
    for (size_t k = 0; k < job.stages.size(); ++k) {
      nlohmann::json report = {{"file", job.stages[k].string()}, {"pass", job.pass}, {"mode", toString(job.mode)},
                               {"classification", std::string(toString(job.mode)) + "-pass"},
                               {"output", "copied"}, {"changed", false}};
      std::string bytes, error;
      if (!readFile(job.stages[k].string(), &bytes)) {
        results[i].log += job.stages[k].string() + ": error: cannot read file\n";
        report["ok"] = false;
        ++results[i].errors;
      } else if (!writeIfChanged(job.outputs[k], bytes, &error)) {
        results[i].log += job.outputs[k].string() + ": error: " + error + "\n";
        report["ok"] = false;
        ++results[i].errors;
      } else {
        report["ok"] = true;
        report["output_file"] = job.outputs[k].string();
      }
      results[i].reports.push_back(report);
    }
  }

  // Convert what is out of date in worker processes.
  const bool tty = ::isatty(2);
  size_t finished = 0;
  auto record = [&](size_t slot, TaskOutcome&& outcome) {
    size_t i = toConvert[slot];
    const BuildJob& job = plan.jobs[i];
    JobResult& result = results[i];
    if (!outcome.completed || !deserialize(outcome.payload, &result)) {
      std::string why = outcome.completed ? "sent back an unreadable result" : outcome.failure;
      std::string stages;
      for (const auto& s : job.stages) stages += (stages.empty() ? "" : ", ") + s.filename().string();
      result = JobResult{};
      result.errors = 1;
      result.log = job.stages.front().string() + ": error: the conversion of pipeline '" + job.id + "' (" + stages +
                   ") " + why + "; the other shaders are converted regardless\n";
      for (const auto& s : job.stages)
        result.reports.push_back({{"file", s.string()}, {"ok", false}, {"failure", why}, {"classification", "failed"}});
    } else {
      nlohmann::json outputs = nlohmann::json::object();
      for (size_t k = 0; k < result.outputs.size() && k < job.outputs.size(); ++k) {
        if (!result.reports[k].value("ok", false)) continue;
        std::string error;
        if (!writeIfChanged(job.outputs[k], result.outputs[k], &error)) {
          result.log += job.outputs[k].string() + ": error: " + error + "\n";
          result.reports[k]["ok"] = false;
          ++result.errors;
          continue;
        }
        outputs[job.outputs[k].string()] = hashBytes(result.outputs[k]);
      }
      for (auto& r : result.reports) {
        r["cached"] = false;
        r["timings_ms"]["pipeline_wall"] = outcome.seconds * 1000.0;
      }
      if (!result.errors) {
        nlohmann::json texts = nlohmann::json::array(), facts = nlohmann::json::array();
        for (const auto& r : result.reports) {
          texts.push_back(reportEntryText(r));
          auto [ok, classification] = reportFacts(r);
          facts.push_back({ok, classification});
        }
        next.jobs[job.id] = {{"key", result.key},
                             {"dependencies", result.dependencies},
                             {"outputs", outputs},
                             {"report_texts", std::move(texts)},
                             {"report_facts", std::move(facts)}};
      }
    }
    ++finished;
    if (tty) drawProgress(finished, toConvert.size(), job.id);
  };
  if (!toConvert.empty()) {
    ensureGlslangInitialized();  // once, before forking: every worker inherits it
    unsigned workers = build.jobs > 0 ? static_cast<unsigned>(build.jobs) : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::string> affinity;
    for (size_t i : toConvert) affinity.push_back(dialectOf(plan.jobs[i].stages.front()));
    runIsolated(
        toConvert.size(), workers, build.jobTimeoutSeconds,
        [&](size_t slot) { return serialize(convertJob(plan.jobs[toConvert[slot]], tool)); }, record, affinity);
    if (tty) std::cerr << "\n";
  }

  // Outputs of pipelines that are gone from the source (or from the manifest): removed, but only
  // files this tool wrote and nobody changed since.
  int removed = 0;
  std::set<std::string> planned;
  for (const auto& job : plan.jobs) planned.insert(job.id);
  for (const auto& [id, entry] : previous.jobs.items()) {
    if (next.jobs.contains(id) || planned.count(id)) continue;
    const nlohmann::json outputs = entry.value("outputs", nlohmann::json::object());
    for (const auto& [path, hash] : outputs.items()) {
      std::string bytes;
      if (insideDirectory(path, outDir) && readFile(path, &bytes) && hashBytes(bytes) == hash.get<std::string>() &&
          fs::remove(path, ec))
        ++removed;
    }
  }

  // Report, in path order; entries of up-to-date pipelines are the cached text.
  std::string shaderEntries;
  size_t shaderCount = 0;
  std::map<std::string, int> counts;
  int converted = 0, cached = 0, copied = 0, failed = 0;
  // One entry into the report and the summary; `total` is the count an ok entry joins.
  auto addEntry = [&](const std::pair<bool, std::string>& facts, int& total, const std::string& text) {
    const auto& [ok, classification] = facts;
    counts[ok ? classification : "failed"]++;
    ++(ok ? total : failed);
    shaderEntries += (shaderCount++ ? ",\n    " : "\n    ") + text;
  };
  std::vector<std::string> dependencies;
  for (const auto& d : plan.extraDependencies) dependencies.push_back(d.string());
  for (size_t i = 0; i < count; ++i) {
    std::cerr << results[i].log;
    errors += results[i].errors;
    for (const auto& s : plan.jobs[i].stages) dependencies.push_back(s.string());
    dependencies.insert(dependencies.end(), results[i].dependencies.begin(), results[i].dependencies.end());
    for (size_t k = 0; k < results[i].reportTexts.size(); ++k)  // up to date
      addEntry(results[i].reportFacts[k], cached, results[i].reportTexts[k]);
    for (const auto& r : results[i].reports)
      addEntry(reportFacts(r), convertsShaders(plan.jobs[i].mode) ? converted : copied, reportEntryText(r));
  }
  nlohmann::json summary;
  summary["tool"] = std::string("stereoshift ") + version();
  summary["source"] = build.source;
  summary["summary"] = {{"pipelines", count}, {"shaders", shaderCount}, {"converted", converted},
                        {"up_to_date", cached}, {"copied_by_pass", copied}, {"failed", failed},
                        {"removed_stale_outputs", removed}};
  summary["classification_counts"] = counts;
  summary["shaders"] = "";  // the entries go in as text
  std::string reportText = summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  static constexpr std::string_view kShadersSlot = "\n  \"shaders\": \"\"";  // unique: one top-level key
  size_t slot = reportText.find(kShadersSlot);
  if (slot != std::string::npos)
    reportText.replace(slot, kShadersSlot.size(),
                       "\n  \"shaders\": [" + shaderEntries + (shaderCount ? "\n  ]" : "]"));
  const std::string reportPath = base.reportPath.empty() ? (outDir / "stereoshift-report.json").string() : base.reportPath;
  if (!writeReportText(reportPath, reportText)) ++errors;

  // The cache changes when something converted or an entry did not carry over.
  std::string error;
  bool cacheUnchanged = !build.noCache && toConvert.empty() && next.jobs.size() == previous.jobs.size() &&
                        fs::exists(cacheFile, ec);
  if (!cacheUnchanged) {
    nlohmann::json cacheJson = {{"format", kCacheFormat}, {"tool", tool}, {"jobs", std::move(next.jobs)}};
    std::vector<std::uint8_t> packed = nlohmann::json::to_msgpack(cacheJson);
    if (!writeAtomically(cacheFile, std::string(packed.begin(), packed.end()), &error))
      std::cerr << cacheFile.string() << ": warning: cannot write the cache (" << error << "); the next run converts everything\n";
  }
  if (!build.depfile.empty() && !writeAtomically(build.depfile, makeDepfile({reportPath}, dependencies), &error)) {
    std::cerr << build.depfile << ": error: " << error << "\n";
    ++errors;
  }

  std::cerr << "stereoshift: " << shaderCount << " shaders from " << build.source << " into " << build.output
            << ": " << converted << " converted, " << cached << " up to date";
  if (copied) std::cerr << ", " << copied << " copied (mono/post/UI passes)";
  if (failed) std::cerr << ", " << failed << " failed";
  if (removed) std::cerr << ", " << removed << " stale outputs removed";
  std::cerr << "\n";
  printErrorSummary(errors);
  return errors ? 1 : 0;
}

}  // namespace stereoshift
