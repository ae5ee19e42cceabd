// What the CLI's commands share: its conversion options, atomic output writing, depfiles and the
// clang-style error summary.
#pragma once

#include "transpiler/stereoshift.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace stereoshift {

struct CliOptions {
  TranspileOptions t;
  std::vector<std::string> inputs;
  std::string output;
  std::string stage, target, eyeSource = "auto", shiftForm = "branch";
  std::string language;  // -x glsl|hlsl
  std::string pipeline;
  std::string reportPath;
  std::string depfile;  // single shader / pipeline: Makefile-style dependencies of the outputs
  bool noCutoff = false, noInvariant = false, noHalo = false;
  bool noPerEyeView = false, noDeferredUnprojection = false;
  std::optional<uint32_t> set, binding, hlslRegister, glBinding;
  std::optional<int> targetVersion;
};

// Registers the conversion options (shared by the main command, `build` and `verify`) on `app`.
void addConversionOptions(CLI::App& app, CliOptions& o);
// Turns the parsed strings into TranspileOptions; an error message when one is invalid.
std::optional<std::string> finishOptions(CliOptions& o);

// Writes through a temporary file renamed into place: a failure never leaves a partial output.
bool writeAtomically(const std::filesystem::path& path, const std::string& bytes, std::string* error);
// Writes the report as JSON to `path` ('-': standard output; empty: nowhere).
bool writeReport(const std::string& path, const nlohmann::json& report);
// The same for a report already in text form ("-": standard output); an identical file is not rewritten.
bool writeReportText(const std::string& path, const std::string& text);
// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log);
// Reads every path into `sources`; each one that cannot be read (or is a directory) is reported to
// `log`. Returns how many failed.
int readSources(const std::vector<std::string>& paths, std::vector<SourceFile>* sources, std::ostream& log);
// "N errors generated." on standard error when N > 0.
void printErrorSummary(int errors);

// Converts one list of stages (a single shader is a pipeline of one) and writes the outputs.
// `outputFor(i)` names each stage's output. Returns the number of errors.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o,
            const std::function<std::string(size_t, const TranspileResult&)>& outputFor, nlohmann::json& reports,
            std::ostream& log);

// Make/Ninja depfile text: `target...: dependency...`.
std::string makeDepfile(const std::vector<std::string>& targets, std::vector<std::string> dependencies);

std::vector<std::string> splitCommas(const std::string& s);

// Every field of the options, for the incremental cache's key: two runs with the same description
// produce the same outputs from the same inputs. A new TranspileOptions field must be added here.
nlohmann::json describeOptions(const TranspileOptions& options);

}  // namespace stereoshift
