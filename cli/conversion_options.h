// The conversion options of the command line: the CliOptions the main command, `build` and
// `verify` share, their registration on a CLI11 app, their translation into TranspileOptions
// (finishOptions, with the messages for a bad value), the sets of values the enumerated ones take,
// and the description of TranspileOptions that keys the incremental cache.
#pragma once

#include "cli/cli11_fwd.h"
#include "transpiler/stereoshift.h"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// How the messages look and how many there are (every subcommand): --color, --no-caret, -q.
struct MessageOptions {
  std::string colour = "auto";  // --color auto|always|never
  bool noCaret = false;         // --no-caret: no source line and caret under located messages
  bool quiet = false;           // -q: no progress bar, no summary line; warnings and errors only
};

struct CliOptions {
  TranspileOptions t;
  MessageOptions messages;
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
  bool noCutoff = false, noInvariant = false, noHalo = false, correctionsOnly = false;
  bool diff = false;  // --diff: print each output's edits as a unified diff against its input
  bool noPerEyeView = false, noDeferredUnprojection = false;
  std::optional<uint32_t> set, binding, hlslRegister, glBinding;
  std::optional<int> targetVersion;
  // Single shader / --pipeline: seconds the conversion may take before it is stopped (0: no limit).
  // 300, like `build --job-timeout`: far beyond any real shader, but an input that never finishes
  // (an include cycle, a pathological expression) still ends with an error.
  double timeoutSeconds = 300;
  // glslc's spellings (the main command): -w drops warnings, -Werror makes them errors (the
  // shader is not written), -MD writes a depfile beside the output.
  bool noWarnings = false;
  std::string warningsAs;  // -W<value>: "error"
  bool depfileBesideOutput = false;
};

// glslc's and clang's spellings CLI11 cannot take as they are, rewritten before the parse:
// -fshader-stage=S (-S S), -fentry-point=F (-e F), -MF FILE (--depfile FILE), -MD, -c (compile
// only: all this tool does) dropped, -f[no-]color-diagnostics and -fdiagnostics-color[=WHEN]
// (--color), -f[no-]caret-diagnostics (--no-caret).
std::vector<std::string> glslcSpellings(int argc, char** argv, bool* depfileBesideOutput);

// Registers --color, --no-caret and -q on `app` (each subcommand has its own).
void addMessageOptions(CLI::App& app, MessageOptions& o);

// Registers the conversion options (shared by the main command, `build` and `verify`) on `app`.
void addConversionOptions(CLI::App& app, CliOptions& o);
// Puts the options `app` has so far into the help's sections (Input, Output, Eye parameters, The
// shift, Per-eye fixes, Analysis and debugging); the others stay under "Options".
void groupConversionOptions(CLI::App& app);
// Turns the parsed strings into TranspileOptions; an error message when one is invalid.
std::optional<std::string> finishOptions(CliOptions& o);

// The options whose values come from a fixed set, and the set: for the messages about a bad or a
// missing value.
const std::map<std::string, std::vector<std::string>>& enumeratedOptions();
// "(a, b, c)": the valid values of an enumerated option.
std::string validValues(const std::string& option);

std::vector<std::string> splitCommas(const std::string& s);

// Why `name` cannot name an injected declaration (the eye block, its instance) in GLSL and HLSL
// alike: empty, not an identifier, reserved, a keyword; nothing when it can. `reproject` checks its
// names with it too.
std::optional<std::string> notAnInjectableName(const std::string& name);

// Every field of the options, for the incremental cache's key: two runs with the same description
// produce the same outputs from the same inputs. A new TranspileOptions field must be added here.
nlohmann::json describeOptions(const TranspileOptions& options);

}  // namespace stereoshift
