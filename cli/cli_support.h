// What the CLI's commands share: its conversion options, atomic output writing, depfiles, the
// clang-style error summary, and the single-shader / --pipeline command itself.
#pragma once

#include "transpiler/stereoshift.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

// CLI11 is declared, not included: it is the heaviest header of the tool (every translation unit that
// included it paid for its parser again), and only the files that register or parse options need it.
namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace stereoshift {

// What diagnostics and reports call a shader read from standard input (the input `-`).
inline constexpr const char* kStdinName = "<stdin>";

struct CliOptions {
  TranspileOptions t;
  std::vector<std::string> inputs;
  std::string output;
  std::string stage, target, eyeSource = "auto", shiftForm = "branch";
  std::string singlePassParams = "auto", eyeRoute = "layer";  // --multiview-params, --eye-route (single-pass stereo)
  std::string language;  // -x glsl|hlsl
  std::string targetEnv, targetSpv;     // --target-env vulkan1.2, --target-spv spv1.5
  std::vector<std::string> stageExts;   // --stage-ext vp=vert (repeatable)
  std::string pipeline;
  std::string reportPath;
  std::string depfile;  // single shader / pipeline: Makefile-style dependencies of the outputs
  bool noCutoff = false, noInvariant = false, noHalo = false;
  bool noPerEyeView = false, noDeferredUnprojection = false;
  std::optional<uint32_t> set, binding, hlslRegister, glBinding;
  std::optional<int> targetVersion;
  // Single shader / --pipeline: seconds the conversion may take before it is stopped (0: no limit).
  // 300, like `build --job-timeout`: far beyond any real shader, but an input that never finishes
  // (an include cycle, a pathological expression) still ends with an error.
  double timeoutSeconds = 300;
};

// Registers the conversion options (shared by the main command, `build` and `verify`) on `app`.
void addConversionOptions(CLI::App& app, CliOptions& o);
// Turns the parsed strings into TranspileOptions; an error message when one is invalid.
std::optional<std::string> finishOptions(CliOptions& o);

// Reports one of CLI11's own parse errors in the house format ("stereoshift: error: ..." and the
// error summary): an unknown option names the nearest known one, an option with a value outside
// its set lists the set. --help and --version are handed back to CLI11. Returns the exit status
// (2, a usage error, like the CLI's other option errors).
int reportParseError(const CLI::App& app, const CLI::ParseError& error, std::ostream& log);
// Edit distance (insertions, deletions, substitutions and adjacent transpositions) of two strings.
size_t editDistance(const std::string& a, const std::string& b);

// Writes through a temporary file renamed into place: a failure never leaves a partial output.
bool writeAtomically(const std::filesystem::path& path, const std::string& bytes, std::string* error);

// The wire format a forked child (single-shader conversion, build worker) sends its result back in:
// length-prefixed byte strings. getString advances `at`; false when `wire` ends early.
void putString(std::string& wire, const std::string& s);
bool getString(const std::string& wire, size_t& at, std::string* s);
// Writes the report as JSON to `path` ('-': standard output; empty: nowhere).
bool writeReport(const std::string& path, const nlohmann::json& report);
// The same for a report already in text form ("-": standard output); an identical file is not rewritten.
bool writeReportText(const std::string& path, const std::string& text);
// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log);
// Reads every path into `sources`; each one that cannot be read (or is a directory) is reported to
// `log`. Returns how many failed.
// Test-only hook: when the environment variable STEREOSHIFT_TEST_HANG names a file (its file name,
// no directory), reading that file never finishes (the process sleeps until it is killed), so the
// tests of --timeout and `build --job-timeout` reach any limit whatever the machine's speed. This
// runs where the conversion runs: in the forked child or build worker, never in build's parent.
// The path "-" is standard input, read once; its SourceFile is named kStdinName.
int readSources(const std::vector<std::string>& paths, std::vector<SourceFile>* sources, std::ostream& log);
// "N errors generated." on standard error when N > 0.
void printErrorSummary(int errors);

// One output waiting to be written ("-": standard output).
struct PendingOutput {
  std::string path;
  std::string bytes;
};
// Writes every output or none: each file's temporary first, then, only when all of them were
// written, the renames (the standard-output ones last). Returns the number of errors.
int writeAllOrNothing(const std::vector<PendingOutput>& outputs, std::ostream& log);

// Converts one list of stages (a single shader is a pipeline of one). `outputFor(i)` names each
// stage's output; the outputs are appended to `outputs` and nothing is written. Returns the number
// of errors.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o, const std::function<std::string(size_t)>& outputFor,
            nlohmann::json& reports, std::ostream& log, std::vector<PendingOutput>* outputs);

// "stereoshift: error: output 'x' is the input 'y'" when an output path names one of the inputs
// (the same file: device and inode, however it is spelt: ./x, an absolute path, a symbolic or a
// hard link). Only existing regular files can be the same file.
std::optional<std::string> outputThatIsAnInput(const std::vector<std::string>& outputs,
                                               const std::vector<std::string>& inputs);

// The single-shader and --pipeline command: converts `paths` (the stages of one pipeline when
// o.pipeline is set) in a forked child, so a crash or a conversion past o.timeoutSeconds costs a
// clear error instead of the tool; writes all outputs or none. Returns the exit status.
int runConvertCommand(const CliOptions& o, const std::vector<std::string>& paths);

// Make/Ninja depfile text: `target...: dependency...`.
std::string makeDepfile(const std::vector<std::string>& targets, std::vector<std::string> dependencies);

std::vector<std::string> splitCommas(const std::string& s);

// Every field of the options, for the incremental cache's key: two runs with the same description
// produce the same outputs from the same inputs. A new TranspileOptions field must be added here.
nlohmann::json describeOptions(const TranspileOptions& options);

}  // namespace stereoshift
