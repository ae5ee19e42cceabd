// `stereoshift build`: a whole shader tree (or the pipelines a scene manifest names) converted
// incrementally, in isolated worker processes, into a mirrored output directory.
//
// The run, in order:
//  1. plan (build_plan): find the shaders, group stages into pipelines by base name, and (with a
//     manifest) give each pipeline the passes that use it; a pipeline used by several passes
//     becomes one variant per pass (`name.<pass>.vert`).
//  2. cache (build_cache): a job whose key (tool, options, every input and included file) matches
//     the cache and whose outputs are still the bytes it wrote is up to date: nothing runs for it.
//  3. schedule (build_schedule): convert the rest in worker processes (a crash or a hang costs one
//     pipeline, not the run), and write each output atomically as it arrives.
//  4. report (build_report), in path order, whatever the number of workers: logs, the JSON report,
//     the cache, the depfile.
#include "cli/build_command.h"

#include "cli/build_cache.h"
#include "cli/build_noop.h"
#include "cli/build_plan.h"
#include "cli/build_report.h"
#include "cli/build_schedule.h"
#include "cli/worker_pool.h"

#include "cli/path_option.h"
#include "cli/unified_diff.h"
#include "transpiler/source/file_io.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// Prints the plan's warnings and errors; false when it has errors (then nothing runs).
bool reportPlanProblems(const Plan& plan) {
  for (const auto& w : plan.warnings) std::cerr << w << "\n";
  for (const auto& e : plan.skippedEntries) std::cerr << e << "\n";
  for (const auto& e : plan.errors) std::cerr << e << "\n";
  return plan.errors.empty();
}

// --diff: every written output of the tree (converted now or up to date) against its source, in the
// plan's order (so the listing does not depend on which worker finished first), on standard output.
// A pipeline that failed wrote nothing and shows nothing; unchanged copies show nothing either.
void printTreeDiffs(const Plan& plan, const std::vector<JobResult>& results) {
  auto side = [](const char* prefix, const std::string& path) {
    return fs::path(path).is_absolute() ? path : prefix + path;  // git's a/ b/ for relative paths
  };
  for (size_t i = 0; i < plan.jobs.size() && i < results.size(); ++i) {
    if (results[i].errors) continue;
    const BuildJob& job = plan.jobs[i];
    for (size_t k = 0; k < job.stages.size() && k < job.outputs.size(); ++k) {
      std::string input, output;
      if (!readFile(job.stages[k].string(), &input) || !readFile(job.outputs[k].string(), &output)) continue;
      const std::string before = side("a/", job.stages[k].string()), after = side("b/", job.outputs[k].string());
      if (input.find('\0') != std::string::npos || output.find('\0') != std::string::npos) {
        if (input != output) std::cout << "Binary files " << before << " and " << after << " differ\n";
        continue;
      }
      std::cout << unifiedDiff(input, output, before, after);
    }
  }
  std::cout.flush();
}

// --dry-run: what the build would do, one line per stage on standard output, nothing written.
int printDryRun(const Plan& plan, const std::vector<size_t>& toConvert) {
  std::set<size_t> converting(toConvert.begin(), toConvert.end());
  size_t shaders = 0, convert = 0, upToDate = 0, copy = 0;
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    const BuildJob& job = plan.jobs[i];
    const bool copies = !convertsShaders(job.mode);
    const char* what = copies ? "copy" : converting.count(i) ? "convert" : "up to date";
    for (size_t k = 0; k < job.stages.size(); ++k) {
      std::cout << what << ": " << job.stages[k].string() << " -> "
                << (k < job.outputs.size() ? job.outputs[k].string() : std::string("?")) << "\n";
      ++shaders;
      ++(copies ? copy : converting.count(i) ? convert : upToDate);
    }
  }
  std::cerr << "stereoshift: dry run: " << shaders << " shaders in " << plan.jobs.size() << " pipelines: " << convert
            << " would be converted, " << upToDate << " up to date, " << copy << " copied; nothing written\n";
  return 0;
}

// What a rebuild with nothing changed would write and print, recorded (build_noop.h): the cache
// this run left, read as that rebuild will read it, with every pipeline up to date. Not recorded
// when that rebuild would convert or fail anything.
void recordRebuild(const Plan& plan, const BuildCommandOptions& build, const CliOptions& base, const std::string& tool,
                   const std::string& reportPath, const std::string& runKey) {
  const fs::path outDir = build.output;
  Cache again = loadCache(outDir / kCacheFile), unused;
  std::vector<JobResult> results(plan.jobs.size());
  if (!reuseUpToDate(plan, tool, true, again, unused, results).empty()) return;
  copyThroughPasses(plan, results);
  const std::vector<fs::path> includeCopies = copyIncludedFiles(plan, results);
  NoopOutcome outcome;
  int errors = static_cast<int>(plan.skippedEntries.size());
  for (const auto& w : plan.warnings) outcome.messages += w + "\n";
  for (const auto& result : results) {
    outcome.messages += result.log;
    errors += result.errors;
  }
  if (errors) return;
  BuildReport report = composeReport(plan, results, 0, build.source, includeCopies);
  outcome.reportPath = reportPath;
  outcome.reportText = report.text;
  if (!build.depfile.empty()) {
    outcome.depfilePath = build.depfile;
    outcome.depfileText = makeDepfile({reportPath}, report.dependencies);
  }
  if (!base.messages.quiet) outcome.messages += summaryLine(report, build.source, build.output);
  recordNoop(build.source, outDir, runKey, outcome, report.dependencies);
}

}  // namespace

void addBuildOptions(CLI::App& build, BuildCommandOptions& o) {
  build.add_option("source", o.source, "Source directory, or a scene manifest (.toml; see docs/trees-and-manifests.md)")
      ->required();
  build.add_option("-o,--output", o.output, "Output directory (mirrors the source tree)")->required()
      ->check(nonEmptyPath());
  build.add_option("-j,--jobs", o.jobs, "Worker processes (default: one per core); the output does not depend on it");
  build.add_option("--depfile", o.depfile, "Write the dependencies of the report (every input and included file) as a depfile");
  build.add_flag("--no-cache", o.noCache, "Convert every shader, even those the incremental cache says are up to date");
  build.add_flag("--dry-run", o.dryRun,
                 "List each pipeline, its stages and outputs and whether it would be converted, is up to date or is "
                 "copied; convert and write nothing");
  build.add_option("--files-from", o.filesFrom,
                   "Convert only the files FILE lists, one path per line (relative to the source directory, or "
                   "absolute inside it), grouped into pipelines as in a tree; what CMake's stereoshift_add_shaders runs")
      ->check(nonEmptyPath());
  build.add_option("--job-timeout", o.jobTimeoutSeconds, "Seconds one pipeline may take before it is stopped and reported (0: no limit)")
      ->capture_default_str();
  build.add_option("--job-memory", o.jobMemoryMiB,
                   "MiB of memory a worker may map before its pipeline is stopped and reported (0: no limit)")
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
  // A shader given to build is not a manifest: said so, not parsed as TOML.
  if (manifestMode && fs::path(build.source).extension() != ".toml") {
    std::cerr << build.source << ": error: build takes a source directory or a scene manifest (.toml), not a shader; "
              << "convert one shader with `stereoshift " << build.source << " -o OUTPUT`\n";
    printErrorSummary(1);
    return 1;
  }
  // An output that is a file stops the build before anything is converted.
  if (fs::exists(outDir, ec) && !fs::is_directory(outDir, ec)) {
    std::cerr << outDir.string() << ": error: the output must be a directory, and this is a file; nothing was converted\n";
    printErrorSummary(1);
    return 1;
  }

  // 0. a rebuild with nothing changed since a run that recorded it (build_noop.h): replayed
  const bool mayReplay = !manifestMode && !build.noCache && !build.dryRun && !base.diff && !build.commandLine.empty();
  const std::string runKey = mayReplay ? noopRunKey(build.commandLine) : std::string();
  if (mayReplay && replayNoop(outDir, runKey)) return 0;
  forgetNoop(outDir);

  // 1. plan
  std::vector<fs::path> listed;
  if (!build.filesFrom.empty()) {
    if (manifestMode) {
      std::cerr << "stereoshift: error: --files-from lists the shaders of a source directory; a manifest names its "
                   "own pipelines\n";
      printErrorSummary(1);
      return 2;
    }
    std::string text;
    if (!readFile(build.filesFrom, &text)) {
      std::cerr << build.filesFrom << ": error: cannot read file: " << unreadableBecause(build.filesFrom) << "\n";
      printErrorSummary(1);
      return 1;
    }
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (!line.empty()) listed.emplace_back(line);
    }
  }
  Plan plan = manifestMode ? planManifest(build.source, outDir, base)
                           : planDirectory(build.source, outDir, base, build.filesFrom.empty() ? nullptr : &listed);
  if (!build.filesFrom.empty()) plan.extraDependencies.emplace_back(build.filesFrom);
  if (!reportPlanProblems(plan)) {
    printErrorSummary(static_cast<int>(plan.errors.size()));
    return 1;
  }
  if (std::string error = checkOutputPlacement(plan, outDir); !error.empty()) {
    std::cerr << error << "\n";
    printErrorSummary(1);
    return 1;
  }

  // 2. cache
  const std::string tool = toolIdentity();
  const fs::path cacheFile = outDir / kCacheFile;
  // Read even with --no-cache: it says which outputs this tool wrote, for removing stale ones.
  Cache previous = loadCache(cacheFile);
  const size_t previousCount = previous.jobs.size();
  Cache next;
  std::vector<JobResult> results(plan.jobs.size());
  const std::vector<size_t> toConvert = reuseUpToDate(plan, tool, !build.noCache, previous, next, results);
  if (build.dryRun) return printDryRun(plan, toConvert);

  // 3. schedule
  copyThroughPasses(plan, results);
  setWorkerMemoryLimit(build.jobMemoryMiB << 20);
  convertInWorkers(plan, toConvert, tool, {build.jobs, build.jobTimeoutSeconds, !base.messages.quiet}, results, next);
  const int removed = removeStaleOutputs(plan, previous, outDir);
  // The #include files the copied and spliced outputs still name: the output tree builds on its own
  // (after the stale outputs went, so a former stage that is now an include file is copied anew).
  const std::vector<fs::path> includeCopies = copyIncludedFiles(plan, results);
  if (base.diff) printTreeDiffs(plan, results);

  // 4. report
  int errors = static_cast<int>(plan.skippedEntries.size());
  for (const auto& result : results) {
    std::cerr << result.log;
    errors += result.errors;
  }
  BuildReport report = composeReport(plan, results, removed, build.source, includeCopies);
  const std::string reportPath = base.reportPath.empty() ? (outDir / "stereoshift-report.json").string() : base.reportPath;
  if (!writeReportText(reportPath, report.text)) ++errors;
  // The cache changes when something converted or an entry did not carry over.
  const bool cacheUnchanged = !build.noCache && toConvert.empty() && next.jobs.size() == previousCount &&
                              fs::exists(cacheFile, ec);
  if (!cacheUnchanged) saveCache(cacheFile, tool, std::move(next));
  const std::string depfileText = build.depfile.empty() ? std::string() : makeDepfile({reportPath}, report.dependencies);
  if (!build.depfile.empty()) {
    if (Status written = writeAtomically(build.depfile, depfileText); !written) {
      std::cerr << located(written.error(), build.depfile).format() << "\n";
      ++errors;
    }
  }
  if (!base.messages.quiet) printSummaryLine(report, build.source, build.output);
  printErrorSummary(errors);
  if (mayReplay && errors == 0) recordRebuild(plan, build, base, tool, reportPath, runKey);
  return errors ? 1 : 0;
}

}  // namespace stereoshift
