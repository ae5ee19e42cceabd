// The report of `stereoshift build`: turns the jobs' results (converted, copied, or replayed from
// the cache) into the JSON report, in path order whatever the number of workers, the dependency
// list for the depfile, and the one-line summary on standard error.
#pragma once

#include "cli/build_job.h"
#include "cli/build_plan.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

// One shader's entry as it sits in the report's "shaders" array (pretty-printed, indented two levels),
// so entries of up-to-date pipelines are copied from the cache as text instead of rebuilt (a no-op
// rebuild of a tree was mostly reading and writing these).
std::string reportEntryText(const nlohmann::json& report);
// What the summary counts of a report entry: whether it is ok, and its classification.
std::pair<bool, std::string> reportFacts(const nlohmann::json& report);
// The entry text of a converted shader (it says "cached": false) made to say it is up to date;
// false when the text is not in that form.
bool markEntryCached(const std::string& convertedText, std::string* cachedText);

struct BuildReport {
  std::string text;                       // the JSON report
  std::vector<std::string> dependencies;  // every input and included file, and the plan's extras
  size_t shaders = 0;
  int converted = 0, upToDate = 0, copied = 0, failed = 0, removed = 0;
  int unchanged = 0;  // of `converted`: nothing to inject, the output is the input byte for byte
  int notWritten = 0;  // converted, but another stage of the pipeline failed: nothing written
};

// The report of a run over `plan`; `results` are per job, `removed` the stale outputs deleted,
// `includeCopies` the #include files copied into the output tree.
BuildReport composeReport(const Plan& plan, const std::vector<JobResult>& results, int removed,
                          const std::string& source, const std::vector<std::filesystem::path>& includeCopies = {});
// The summary line a run prints (unless --quiet), with its newline.
std::string summaryLine(const BuildReport& report, const std::string& source, const std::string& output);
// "stereoshift: N shaders from SRC into OUT: ..." on standard error.
void printSummaryLine(const BuildReport& report, const std::string& source, const std::string& output);

}  // namespace stereoshift
