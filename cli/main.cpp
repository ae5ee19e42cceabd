// stereoshift: a thin command line over the library (transpiler/stereoshift.h).
//
//   stereoshift [options] <input> -o <output>          one shader
//   stereoshift [options] --pipeline a.vert,a.geom,a.frag -o <dir>   one pipeline
//   stereoshift build <src-dir | scene.toml> -o <out-dir> [options]   a whole tree or scene
//   stereoshift reproject -o <dir> [--target LANG ...] [options]      the depth-reprojection pass
#include "cli/build_command.h"
#include "cli/cli_support.h"
#include "cli/persistent_worker.h"
#include "cli/reproject_command.h"
#include "cli/service_client.h"
#include "cli/verify_command.h"
#include "cli/worker_pool.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/stereoshift.h"

#include "cli/path_option.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace stereoshift;

// The output file for `input` in the directory `dir`: its own name, with the extension of another
// output language appended (a.vert -> a.vert.spv, as glslc names it).
static std::string outputInDirectory(const std::string& dir, const std::string& input, const TranspileOptions& t) {
  std::string name = std::filesystem::path(input).filename().string();
  std::string extension = defaultOutputExtension(SourceFile{input, {}}, t);  // the input's own for GLSL
  if (!name.ends_with(extension)) name += extension;
  return (std::filesystem::path(dir) / name).string();
}

// `stereoshift verify`: its options checked, its inputs read, the verdict printed.
static int runVerify(CliOptions& v, const VerifyCommandOptions& verifyOptions) {
  if (auto error = finishOptions(v)) {
    std::cerr << "stereoshift: error: " << *error << "\n";
    printErrorSummary(1);
    return 2;
  }
  // verify writes nothing but its verdict: --report and --diff (shared with the conversion's
  // options) would be silently ignored, so they are refused (-o and --depfile are not verify
  // options at all; --target is read: the conversion it checks is the one to that language).
  std::vector<std::string> ignored;
  if (!v.reportPath.empty()) ignored.push_back("--report");
  if (v.diff) ignored.push_back("--diff");
  if (!ignored.empty()) {
    std::string list;
    for (const auto& option : ignored) list += (list.empty() ? "" : ", ") + option;
    std::cerr << "stereoshift: error: verify writes no output (it runs the conversion as SPIR-V on the device and "
                 "prints its verdict; --json for a machine-readable one): "
              << list << " would be ignored; convert with `stereoshift FILE ...` for those\n";
    printErrorSummary(1);
    return 2;
  }
  std::vector<SourceFile> sources;
  if (int failed = readSources(v.inputs, &sources, std::cerr)) {
    printErrorSummary(failed);
    return 1;
  }
  if (sources.empty()) {
    std::cerr << "stereoshift: error: no input file (see verify --help)\n";
    printErrorSummary(1);
    return 2;
  }
  return runVerifyCommand(sources, v.t, verifyOptions);
}

// The command line, run in this process: what main() ends in (directly, through @params files or the
// persistent worker) and what a conversion-service worker runs for each request (cli/service_server.h).
static int runCommandLine(int argc, char** argv) {
  CLI::App app{"stereoshift: converts mono shaders (GLSL, ESSL, HLSL, SPIR-V) into stereoscopic ones"};
  app.set_version_flag("--version", std::string("stereoshift ") + version());
  CliOptions o;
  addConversionOptions(app, o);
  app.add_option("input", o.inputs, "Input shader (.vert .frag ..., .vs .fs ..., .vsh .fsh, .glsl/.hlsl/.fx with -S or #pragma shader_stage, .spv); '-': standard input");
  app.add_option("-o,--output", o.output, "Output file (a directory with --pipeline); '-' or none: standard output")
      ->check(nonEmptyPath());
  app.add_option("--pipeline", o.pipeline, "Comma-separated stages of one pipeline; only its last pre-rasterization stage is shifted");
  app.add_option("--depfile", o.depfile,
                 "Write the outputs' dependencies (the inputs and every #included file) as a Makefile-style depfile");
  app.add_option("--timeout", o.timeoutSeconds, "Seconds the conversion may take before it is stopped and reported (0: no limit)")
      ->capture_default_str();
  app.add_flag("-w", o.noWarnings, "Suppress warnings (as glslc)");
  app.add_option("-W", o.warningsAs, "-Werror: treat warnings as errors, nothing written (as glslc)")->check(CLI::IsMember({"error"}));
  ServiceOptions serviceOptions;
  addServiceOptions(app, serviceOptions);
  groupConversionOptions(app);  // the main command's own options (-o, --pipeline, -w...) into the sections

  CliOptions b;
  BuildCommandOptions buildOptions;
  auto* build = app.add_subcommand(
      "build", "Convert a whole shader tree (stages grouped into pipelines by base name) or a scene manifest");
  addConversionOptions(*build, b);
  addBuildOptions(*build, buildOptions);
  groupConversionOptions(*build);

  CliOptions v;
  VerifyCommandOptions verifyOptions;
  auto* verify = app.add_subcommand(
      "verify", "Run the original and the stereo shader on the CPU Vulkan driver (lavapipe) and check the shift");
  addConversionOptions(*verify, v);
  verify->add_option("input", v.inputs, "Shader, or the stages of one pipeline (only pre-rasterization stages run)");
  verify->add_option("--separation", verifyOptions.separation, "Separation used for the check")->capture_default_str();
  verify->add_option("--convergence", verifyOptions.convergence, "Convergence used for the check")->capture_default_str();
  verify->add_flag("--json", verifyOptions.json, "Machine-readable result");
  groupConversionOptions(*verify);

  ReprojectCliOptions reprojectOptions;
  auto* reproject = addReprojectCommand(app, reprojectOptions);

  // glslc's spellings (-fshader-stage=vert, -MD, -MF FILE, -c) into this tool's.
  std::vector<std::string> spelled = glslcSpellings(argc, argv, &o.depfileBesideOutput);
  std::vector<char*> args;
  for (auto& a : spelled) args.push_back(a.data());
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return reportParseError(app, e, std::cerr);
  }

  // The messages of the command that runs, in its style, from here on.
  const MessageOptions& messages = *reproject ? reprojectOptions.messages
                                   : *verify  ? v.messages
                                   : *build   ? b.messages
                                              : o.messages;
  DiagnosticStream styled({!messages.noCaret, colourWanted(messages.colour)});

  if (*reproject) return runReprojectCommand(reprojectOptions);

  if (*verify) return runVerify(v, verifyOptions);

  if (*build) {
    if (auto error = finishOptions(b)) {
      std::cerr << "stereoshift: error: " << *error << "\n";
      printErrorSummary(1);
      return 2;
    }
    buildOptions.commandLine = spelled;
    return runBuildCommand(buildOptions, b);
  }

  if (auto error = finishOptions(o)) {
    std::cerr << "stereoshift: error: " << *error << "\n";
    printErrorSummary(1);
    return 2;
  }
  // -MD: glslc's depfile beside the output, <output>.d.
  if (o.depfileBesideOutput && o.depfile.empty() && !o.output.empty() && o.output != "-") o.depfile = o.output + ".d";
  std::vector<std::string> paths = o.pipeline.empty() ? o.inputs : splitCommas(o.pipeline);
  if (!o.pipeline.empty()) paths.insert(paths.end(), o.inputs.begin(), o.inputs.end());
  if (paths.empty()) {
    std::cerr << "stereoshift: error: no input file (see --help)\n";
    printErrorSummary(1);
    return 2;
  }
  // -o DIRECTORY/ (or an existing directory): each input converted on its own into it, as glslc
  // does with several files.
  std::error_code ec;
  const bool outputIsDirectory = o.pipeline.empty() && !o.output.empty() && o.output != "-" &&
                                 (o.output.back() == '/' || std::filesystem::is_directory(o.output, ec));
  if (paths.size() > 1 && o.pipeline.empty() && !outputIsDirectory) {
    std::cerr << "stereoshift: error: several inputs need --pipeline (one pipeline), or -o DIRECTORY/ (each converted "
                 "on its own), or 'stereoshift build' (a tree)\n";
    printErrorSummary(1);
    return 2;
  }
  if (outputIsDirectory) {
    if (!o.depfile.empty() && paths.size() > 1) {
      std::cerr << "stereoshift: error: --depfile names one file; with several inputs use -MD (one beside each output)\n";
      printErrorSummary(1);
      return 2;
    }
    int status = 0;
    for (const std::string& path : paths) {
      CliOptions one = o;
      one.output = outputInDirectory(o.output, path, o.t);
      if (o.depfileBesideOutput && o.depfile.empty()) one.depfile = one.output + ".d";
      status = std::max(status, runConvertCommand(one, {path}));
    }
    return status;
  }
  if (serviceWanted(serviceOptions))
    if (auto status = runThroughService(argc, argv, serviceOptions, o, &runCommandLine)) return *status;
  return runConvertCommand(o, paths);
}

// Bazel calls the tool with @params files, or starts it as a persistent worker (--persistent_worker):
// both end in runCommandLine (cli/persistent_worker.h).
int main(int argc, char** argv) { return runToolEntry(argc, argv, runCommandLine); }
