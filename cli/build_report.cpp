// The report of `stereoshift build`: the results of every job, in path order, as the JSON report
// and the summary line.
#include "cli/build_report.h"

#include <iostream>
#include <sstream>
#include <map>
#include <string_view>

namespace stereoshift {

std::string reportEntryText(const nlohmann::json& report) {
  std::string text = report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace), indented;
  indented.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    indented += c;
    if (c == '\n') indented += "    ";
  }
  return indented;
}

std::pair<bool, std::string> reportFacts(const nlohmann::json& report) {
  return {report.value("ok", false), report.value("classification", "?")};
}

// A converted entry holds "cached": false as a top-level key (indented 6 spaces in the entry's
// text; nested keys are indented further, so the match is the top-level one); an up-to-date one
// says true. Not necessarily first: "analysis" and "analysis_reason" sort before it.
constexpr std::string_view kConvertedKey = "\n      \"cached\": false,";
constexpr std::string_view kCachedKey = "\n      \"cached\": true,";

bool markEntryCached(const std::string& convertedText, std::string* cachedText) {
  if (!convertedText.starts_with("{")) return false;
  size_t at = convertedText.find(kConvertedKey);
  if (at == std::string::npos) return false;
  *cachedText = convertedText.substr(0, at) + std::string(kCachedKey) + convertedText.substr(at + kConvertedKey.size());
  return true;
}

BuildReport composeReport(const Plan& plan, const std::vector<JobResult>& results, int removed,
                          const std::string& source, const std::vector<std::filesystem::path>& includeCopies) {
  BuildReport report;
  report.removed = removed;
  std::string shaderEntries;
  std::map<std::string, int> counts;
  // One entry into the report and the summary; `total` is the count an ok entry joins.
  auto addEntry = [&](const std::pair<bool, std::string>& facts, int& total, const std::string& text) {
    const auto& [ok, classification] = facts;
    counts[ok ? classification : "failed"]++;
    ++(ok ? total : report.failed);
    shaderEntries += (report.shaders++ ? ",\n    " : "\n    ") + text;
  };
  for (const auto& d : plan.extraDependencies) report.dependencies.push_back(d.string());
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    for (const auto& s : plan.jobs[i].stages) report.dependencies.push_back(s.string());
    report.dependencies.insert(report.dependencies.end(), results[i].dependencies.begin(),
                               results[i].dependencies.end());
    for (size_t k = 0; k < results[i].reportTexts.size(); ++k)  // up to date
      addEntry(results[i].reportFacts[k], report.upToDate, results[i].reportTexts[k]);
    for (const auto& r : results[i].reports) {
      bool converts = convertsShaders(plan.jobs[i].mode);
      // A stage that converted while another stage of its pipeline failed is not written (the
      // pipeline is all or nothing): not counted as converted.
      bool unwritten = r.value("ok", false) && r.value("output", "").starts_with("not written");
      addEntry(reportFacts(r), unwritten ? report.notWritten : converts ? report.converted : report.copied,
               reportEntryText(r));
      if (converts && r.value("ok", false) && r.value("output", "") == "copied") ++report.unchanged;
    }
  }
  nlohmann::json summary;
  summary["tool"] = std::string("stereoshift ") + version();
  summary["source"] = source;
  summary["summary"] = {{"pipelines", plan.jobs.size()}, {"shaders", report.shaders},
                        {"converted", report.converted}, {"converted_unchanged", report.unchanged},
                        {"up_to_date", report.upToDate},
                        {"copied_by_pass", report.copied}, {"failed", report.failed},
                        {"not_written", report.notWritten},
                        {"removed_stale_outputs", removed}};
  // The #include files copied into the output tree (copyIncludedFiles), relative to it.
  if (!includeCopies.empty()) {
    nlohmann::json copied = nlohmann::json::array();
    for (const auto& c : includeCopies) copied.push_back(c.lexically_relative(plan.outputDir).generic_string());
    summary["include_files"] = copied;
  }
  summary["classification_counts"] = counts;
  summary["shaders"] = "";  // the entries go in as text
  report.text = summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  static constexpr std::string_view kShadersSlot = "\n  \"shaders\": \"\"";  // unique: one top-level key
  size_t slot = report.text.find(kShadersSlot);
  if (slot != std::string::npos)
    report.text.replace(slot, kShadersSlot.size(),
                        "\n  \"shaders\": [" + shaderEntries + (report.shaders ? "\n  ]" : "]"));
  return report;
}

std::string summaryLine(const BuildReport& report, const std::string& source, const std::string& output) {
  std::ostringstream line;
  line << "stereoshift: " << report.shaders << " shaders from " << source << " into " << output << ": "
       << report.converted << " converted, " << report.upToDate << " up to date";
  if (report.copied) line << ", " << report.copied << " copied (mono/post/UI passes)";
  if (report.failed) line << ", " << report.failed << " failed";
  if (report.notWritten) line << ", " << report.notWritten << " not written (another stage of their pipeline failed)";
  if (report.removed) line << ", " << report.removed << " stale outputs removed";
  // Converted, but nothing to inject (2D, fragment, already stereo): written as they were.
  if (report.unchanged) line << "; " << report.unchanged << " of the converted unchanged (written as they were)";
  line << "\n";
  return line.str();
}

void printSummaryLine(const BuildReport& report, const std::string& source, const std::string& output) {
  std::cerr << summaryLine(report, source, output);
}

}  // namespace stereoshift
