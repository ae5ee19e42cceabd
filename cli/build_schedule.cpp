// The schedule of `stereoshift build`: copy-through in the parent, conversions in worker processes,
// the worker's side of a conversion (its result travels through result_codec.h), progress.
#include "cli/build_schedule.h"

#include "cli/cli_support.h"
#include "cli/process_failure.h"
#include "cli/result_codec.h"
#include "cli/worker_pool.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/source/file_io.h"

#include <unistd.h>

#include <algorithm>
#include <map>
#include <cstring>
#include <iostream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// Runs in a worker: converts one pipeline, keeping everything in memory.
JobResult convertJob(const BuildJob& job, const std::string& tool) {
  JobResult result;
  std::ostringstream log;
  std::vector<SourceFile> sources;
  std::vector<std::string> paths;
  for (const auto& p : job.stages) paths.push_back(p.string());
  result.errors += readSources(paths, &sources, log);
  result.replayable = result.errors == 0;  // a read error says nothing about the bytes
  if (!result.errors) {
    std::vector<TranspileResult> converted = transpilePipeline(sources, job.options);
    result.outputs.resize(converted.size());
    for (size_t i = 0; i < converted.size(); ++i) {
      auto& r = converted[i];
      int diagnosticErrors = printDiagnostics(r.diagnostics, log);
      if (!r.passLog.empty()) log << r.passLog;
      for (const auto& inc : r.includedFiles) result.dependencies.push_back(inc);
      r.report["ok"] = r.ok;
      // Which pipeline the stage was grouped into (the name without its stage part): with the
      // report's stage_reason, how `build` read the tree.
      r.report["pipeline"] = job.id;
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
  result.key = jobKey(tool, job, result.dependencies, [&](const std::string& path) {
    for (size_t i = 0; i < sources.size() && i < job.stages.size(); ++i)
      if (job.stages[i].string() == path) return hashBytes(sources[i].contents);
    return hashFile(path);
  });
  return result;
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
  // Pipelines, as the jobs run (a pipeline's stages convert together); the summary counts shaders.
  std::cerr << "\r[" << bar << "] " << done << "/" << total << " pipelines " << what << "\x1b[K" << std::flush;
}

// The result of a job whose worker did not send one back (crashed, timed out, garbled).
JobResult workerFailure(const BuildJob& job, const std::string& why) {
  std::string stages;
  for (const auto& s : job.stages) stages += (stages.empty() ? "" : ", ") + s.filename().string();
  JobResult result;
  result.errors = 1;
  result.log = job.stages.front().string() + ": error: the conversion of pipeline '" + job.id + "' (" + stages +
               ") " + why + "; the other shaders are converted regardless\n";
  for (const auto& s : job.stages)
    result.reports.push_back({{"file", s.string()}, {"ok", false}, {"failure", why}, {"classification", "failed"}});
  return result;
}

}  // namespace

void copyThroughPasses(const Plan& plan, std::vector<JobResult>& results) {
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    const BuildJob& job = plan.jobs[i];
    if (convertsShaders(job.mode)) continue;
    for (size_t k = 0; k < job.stages.size(); ++k) {
      nlohmann::json report = {{"file", job.stages[k].string()}, {"pass", job.pass}, {"mode", toString(job.mode)},
                               {"classification", std::string(toString(job.mode)) + "-pass"},
                               {"output", "copied"}, {"changed", false}};
      std::string bytes;
      Status written = Done{};
      if (!readFile(job.stages[k].string(), &bytes)) {
        results[i].log += job.stages[k].string() + ": error: cannot read file\n";
        report["ok"] = false;
        ++results[i].errors;
      } else if (written = writeIfChanged(plan.outputDir, job.outputs[k], bytes); !written) {
        results[i].log += located(written.error(), job.outputs[k].string()).format() + "\n";
        report["ok"] = false;
        ++results[i].errors;
      } else {
        report["ok"] = true;
        report["output_file"] = job.outputs[k].string();
      }
      results[i].reports.push_back(report);
    }
  }
}

void convertInWorkers(const Plan& plan, const std::vector<size_t>& toConvert, const std::string& tool,
                      const ScheduleOptions& options, std::vector<JobResult>& results, Cache& next) {
  if (toConvert.empty()) return;
  const bool tty = options.progress && ::isatty(2);
  size_t finished = 0;
  // Jobs whose worker crashed: converted again down the crash ladder (process_failure.h), each round
  // without what the last attempt died in, once every job of the round before is done.
  struct Retry {
    size_t job;          // index into plan.jobs
    BuildJob converted;  // the job as the next rung converts it
    TaskOutcome first;   // the first crash: what the user is told when no rung converts
    std::vector<std::pair<TaskOutcome, std::string>> climbed;  // each crash and the rung taken after it
  };
  std::vector<Retry> retries, nextRetries;
  bool retrying = false;
  auto record = [&](size_t slot, TaskOutcome&& outcome) {
    size_t i = retrying ? retries[slot].job : toConvert[slot];
    const BuildJob& job = plan.jobs[i];
    JobResult& result = results[i];
    if (!outcome.completed) {
      Retry next = retrying ? std::move(retries[slot]) : Retry{i, job, outcome, {}};
      std::string rung;
      if (climbCrashLadder(outcome, next.converted.options, &rung)) {
        next.climbed.emplace_back(outcome, rung);
        nextRetries.push_back(std::move(next));
        return;
      }
      if (retrying) outcome = std::move(next.first);
    }
    bool decoded = outcome.completed && decodeJobResult(outcome.payload, &result);
    std::string failedRung;  // the messages of a rung that ended with errors, as notes after the crash
    if (retrying && decoded && result.errors > 0) {
      failedRung = rungMessagesAsNotes(result.log);
      outcome = std::move(retries[slot].first);  // the crash is what the user is told
      decoded = false;
    }
    if (retrying && decoded) {
      // Said in the log and each stage's report: the output comes from a later rung.
      nlohmann::json rungs = nlohmann::json::array();
      for (const auto& [crash, rung] : retries[slot].climbed) {
        result.log += job.stages.front().string() + ": warning: " + crashWords(crash) + "; converted again " + rung + "\n";
        rungs.push_back({{"crashed", crashWords(crash)}, {"then", rung}});
      }
      for (auto& r : result.reports) r["crash_recovery"] = rungs;
    }
    if (!decoded) {
      if (outcome.completed) {
        result = workerFailure(job, "sent back an unreadable result");
      } else if (outcome.phase.empty()) {
        result = workerFailure(job, outcome.failure);
      } else {
        // Which part of the tool it died in; a known trigger in any of the pipeline's stages.
        std::vector<std::string> stages;
        for (const auto& stage : job.stages) stages.push_back(stage.string());
        ProcessFailureText failure = describeProcessFailure(outcome, stages);
        result = workerFailure(job, "failed: " + failure.what);
        for (const auto& note : failure.notes) result.log += note + "\n";
        result.log += failedRung;
      }
    } else {
      nlohmann::json outputs = nlohmann::json::object(), stamps = nlohmann::json::object();
      bool writeFailed = false;
      // A pipeline is all or nothing: when one stage failed, the stages that converted are not
      // written either, so the output tree keeps the pipeline's last good conversion whole.
      const bool pipelineFailed = result.errors > 0;
      for (size_t k = 0; k < result.outputs.size() && k < job.outputs.size(); ++k) {
        if (!result.reports[k].value("ok", false)) continue;
        if (pipelineFailed) {
          result.reports[k].erase("output_file");
          result.reports[k]["output"] = "not written: another stage of the pipeline failed";
          continue;
        }
        if (Status written = writeIfChanged(plan.outputDir, job.outputs[k], result.outputs[k]); !written) {
          result.log += located(written.error(), job.outputs[k].string()).format() + "\n";
          result.reports[k]["ok"] = false;
          ++result.errors;
          writeFailed = true;
          continue;
        }
        outputs[job.outputs[k].string()] = hashBytes(result.outputs[k]);
        stamps[job.outputs[k].string()] = fileStamp(job.outputs[k]);
      }
      // What the outputs just written include: the include copies and the next no-op build need
      // not read them back. Unknown when a stage was not written (the disk keeps an older output).
      result.outputIncludesKnown = !writeFailed && !pipelineFailed && result.outputs.size() == job.outputs.size();
      for (size_t k = 0; result.outputIncludesKnown && k < job.outputs.size(); ++k)
        for (auto& header : includedFiles(job.stages[k], result.outputs[k], job.options.includeDirs))
          result.outputIncludes.push_back(header.string());
      for (auto& r : result.reports) {
        r["cached"] = false;
        r["timings_ms"]["pipeline_wall"] = outcome.seconds * 1000.0;
      }
      // A failure to write depends on the disk, not on the inputs: never cached.
      if (!writeFailed && (!result.errors || result.replayable)) recordFinished(next, plan, job, result, std::move(outputs), std::move(stamps));
    }
    ++finished;
    if (tty) drawProgress(finished, toConvert.size(), job.id);
  };
  ensureGlslangInitialized();  // once, before forking: every worker inherits it
  unsigned workers = options.jobs > 0 ? static_cast<unsigned>(options.jobs) : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::string> affinity;
  for (size_t i : toConvert) affinity.push_back(dialectOf(plan.jobs[i].stages.front()));
  runIsolated(
      toConvert.size(), workers, options.jobTimeoutSeconds,
      [&](size_t slot) { return encodeJobResult(convertJob(plan.jobs[toConvert[slot]], tool)); }, record, affinity);
  while (!nextRetries.empty()) {
    retries = std::move(nextRetries);
    nextRetries.clear();
    retrying = true;
    runIsolated(
        retries.size(), workers, options.jobTimeoutSeconds,
        [&](size_t slot) { return encodeJobResult(convertJob(retries[slot].converted, tool)); }, record);
  }
  if (tty) std::cerr << "\n";
}

std::vector<fs::path> copyIncludedFiles(const Plan& plan, std::vector<JobResult>& results) {
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(plan.root, ec);
  const fs::path outCanonical = fs::weakly_canonical(plan.outputDir, ec);
  // What the written outputs still #include, resolved from the stage they came from (the output
  // mirrors it), then what those files include in turn: SPIRV-Cross outputs name none (they carry
  // the included code), copied and spliced ones name the source's.
  struct Needed {
    size_t job;         // the first job whose output needs the file
    bool read = false;  // `bytes` holds the file (read once: scanned for its own includes, then copied)
    std::string bytes;
  };
  std::map<fs::path, Needed> needed;
  std::vector<std::pair<fs::path, size_t>> pending;
  for (size_t i = 0; i < results.size() && i < plan.jobs.size(); ++i) {
    const BuildJob& job = plan.jobs[i];
    if (results[i].outputIncludesKnown) {
      for (const auto& header : results[i].outputIncludes) pending.emplace_back(header, i);
      continue;
    }
    // Otherwise what the outputs on disk name (a copy-through pass, a pipeline kept from a former run).
    for (size_t k = 0; k < job.stages.size() && k < job.outputs.size(); ++k) {
      std::string text;
      if (!readFile(job.outputs[k].string(), &text)) continue;  // never written, or gone
      for (auto& header : includedFiles(job.stages[k], text, job.options.includeDirs)) pending.emplace_back(header, i);
    }
  }
  while (!pending.empty()) {
    auto [file, job] = pending.back();
    pending.pop_back();
    if (!insideDirectory(file, root) || insideDirectory(file, outCanonical)) continue;
    auto [entry, added] = needed.emplace(file, Needed{job});
    if (!added) continue;
    Needed& n = entry->second;
    n.read = readFile(file.string(), &n.bytes);
    if (n.read)
      for (auto& header : includedFiles(file, n.bytes, plan.jobs[job].options.includeDirs)) pending.emplace_back(header, job);
  }
  std::vector<fs::path> copied;
  for (const auto& [file, n] : needed) {
    const fs::path output = plan.outputDir / file.lexically_relative(root);
    if (!n.read) {
      results[n.job].log += file.string() + ": error: cannot read the included file to copy it into the output tree\n";
      ++results[n.job].errors;
      continue;
    }
    if (Status written = writeIfChanged(plan.outputDir, output, n.bytes); !written) {
      results[n.job].log += located(written.error(), output.string()).format() + "\n";
      ++results[n.job].errors;
      continue;
    }
    copied.push_back(output);
  }
  return copied;
}

}  // namespace stereoshift
