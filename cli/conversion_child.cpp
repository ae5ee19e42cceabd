// The forked child of the single-shader command (see conversion_child.h).
#include "cli/conversion_child.h"

#include "cli/convert_command.h"
#include "cli/depfile.h"
#include "cli/diagnostic_output.h"
#include "cli/process_failure.h"
#include "cli/source_reading.h"
#include "cli/worker_pool.h"

#include <cstdio>
#include <cstring>
#include <sstream>
#include <cstdlib>
#include <iostream>

namespace stereoshift {

namespace {

// Runs in the conversion child: reads and converts, prints the diagnostics, writes nothing.
ConversionRun convertInChild(const CliOptions& o, const std::vector<std::string>& paths,
                             const std::function<std::string(size_t)>& outputFor) {
  ConversionRun run;
  std::vector<SourceFile> sources;
  run.errors = readSources(paths, &sources, std::cerr);
  if (run.errors) return run;
  nlohmann::json reports = nlohmann::json::array();
  run.errors = convert(sources, o, outputFor, reports, std::cerr, &run.outputs);
  if (!run.errors && !o.depfile.empty()) {
    if (auto text = conversionDepfile(reports, sources)) {
      run.depfileText = std::move(*text);
    } else {
      std::cerr << "stereoshift: error: --depfile needs an output file (-o)\n";
      ++run.errors;
    }
  }
  if (run.errors) {
    // A failed pipeline writes nothing, so no stage's report names an output file.
    run.outputs.clear();
    run.depfileText.clear();
    for (auto& r : reports) r.erase("output_file");
  }
  run.hasReport = true;
  run.report = sources.size() == 1 && !reports.empty() ? reports[0] : reports;
  return run;
}

// Says, in a warning per climbed rung and in the report ("crash_recovery", on each stage's), that the
// output comes from a later rung of the crash ladder than the first attempt.
void attachCrashRecovery(const std::string& shown, const std::vector<std::pair<TaskOutcome, std::string>>& climbed,
                         ConversionRun* run) {
  nlohmann::json rungs = nlohmann::json::array();
  for (const auto& [crash, rung] : climbed) {
    std::cerr << shown << ": warning: " << crashWords(crash) << "; converted again " << rung << "\n";
    rungs.push_back({{"crashed", crashWords(crash)}, {"then", rung}});
  }
  if (run->report.is_array()) {
    for (auto& stage : run->report) stage["crash_recovery"] = rungs;
  } else if (run->report.is_object()) {
    run->report["crash_recovery"] = rungs;
  }
}

}  // namespace

bool runConversionChild(const CliOptions& o, const std::vector<std::string>& paths,
                        const std::function<std::string(size_t)>& outputFor, ConversionRun* run) {
  // The conversion runs in a forked child: a crash in the front end (glslang overflows its stack
  // on some inputs) or a conversion past the time limit becomes a clear error instead of a core
  // dump or a hang. STEREOSHIFT_NO_FORK=1 keeps it in process, for a debugger (no time limit then).
  if (const char* noFork = std::getenv("STEREOSHIFT_NO_FORK"); noFork && *noFork && std::string(noFork) != "0") {
    *run = convertInChild(o, paths, outputFor);
  } else {
    const std::string shown = paths.front() == "-" ? std::string(kStdinName) : paths.front();  // as diagnostics name it
    // One conversion in a forked child. Its result comes back framed with the messages it held
    // back: a second attempt's messages are the user's only when it succeeds, a first attempt's go
    // out as they are written.
    auto attempt = [&](const CliOptions& options, bool holdMessages) {
      return runIsolatedOnce(
          [&] {
            std::ostringstream held;
            std::streambuf* direct = holdMessages ? std::cerr.rdbuf(held.rdbuf()) : nullptr;
            std::string wire = encodeConversionRun(convertInChild(options, paths, outputFor));
            if (direct) std::cerr.rdbuf(direct);
            std::cout.flush();
            std::cerr.flush();
            std::fflush(nullptr);
            std::string messages = held.str();
            uint64_t size = messages.size();
            return std::string(reinterpret_cast<const char*>(&size), sizeof size) + messages + wire;
          },
          options.timeoutSeconds);
    };
    // The messages and the run out of a completed attempt; false when the payload is not one.
    auto unframe = [](const TaskOutcome& done, std::string* messages, ConversionRun* result) {
      uint64_t size = 0;
      if (done.payload.size() < sizeof size) return false;
      std::memcpy(&size, done.payload.data(), sizeof size);
      if (size > done.payload.size() - sizeof size) return false;
      *messages = done.payload.substr(sizeof size, size);
      return decodeConversionRun(done.payload.substr(sizeof size + size), result);
    };
    TaskOutcome outcome = attempt(o, false);
    // A crash: once more down the crash ladder (process_failure.h), each attempt without what the last
    // one died in. The first attempt that converts is the result, said in a warning and the report;
    // when none does, the first crash is what the user is told.
    CliOptions again = o;
    std::string rung;
    std::vector<std::pair<TaskOutcome, std::string>> climbed;  // each crash and the rung taken after it
    std::string failedRung;  // the messages of a rung that ended with errors, as notes after the crash
    for (TaskOutcome last = outcome; climbCrashLadder(last, again.t, &rung);) {
      climbed.emplace_back(last, rung);
      last = attempt(again, true);
      std::string messages;
      ConversionRun candidate;
      if (!last.completed) continue;
      if (unframe(last, &messages, &candidate) && candidate.errors == 0) {
        std::cerr << messages;
        attachCrashRecovery(shown, climbed, &candidate);
        *run = std::move(candidate);
        return true;
      }
      failedRung = rungMessagesAsNotes(messages);
      break;
    }
    if (!outcome.completed) {
      // runIsolated's words for a task it stopped at the limit start with "timed out".
      if (outcome.failure.rfind("timed out", 0) == 0) {
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g", o.timeoutSeconds);
        std::cerr << shown << ": error: conversion exceeded the " << limit << " s time limit (--timeout)"
                  << (outcome.phase.empty() ? "" : " in " + outcome.phase) << "; no output was written\n";
      } else {
        ProcessFailureText failure = describeProcessFailure(outcome, {paths.front()});
        std::cerr << shown << ": error: " << failure.what << " while converting this shader; no output was written\n";
        for (const auto& note : failure.notes) std::cerr << note << "\n";
        std::cerr << failedRung;
      }
      printErrorSummary(1);
      return false;
    }
    std::string messages;  // none: the first attempt's went out as written
    if (!unframe(outcome, &messages, run)) {
      std::cerr << shown << ": error: stereoshift's conversion process answered garbage; no output was written\n";
      printErrorSummary(1);
      return false;
    }
  }
  return true;
}

}  // namespace stereoshift
