// stereoshift: a thin command line over the library (transpiler/stereoshift.h).
//
//   stereoshift [options] <input> -o <output>          one shader
//   stereoshift [options] --pipeline a.vert,a.geom,a.frag -o <dir>   one pipeline
//   stereoshift build <src-dir | scene.toml> -o <out-dir> [options]   a whole tree or scene
#include "cli/build_command.h"
#include "cli/cli_support.h"
#include "cli/verify_command.h"
#include "cli/worker_pool.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/stereoshift.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace stereoshift;

int main(int argc, char** argv) {
  CLI::App app{"stereoshift: converts mono shaders (GLSL, ESSL, HLSL, SPIR-V) into stereoscopic ones"};
  app.set_version_flag("--version", std::string("stereoshift ") + version());
  CliOptions o;
  addConversionOptions(app, o);
  app.add_option("input", o.inputs, "Input shader (.vert .tesc .tese .geom .frag .comp .mesh .task, .hlsl, .spv)");
  app.add_option("-o,--output", o.output, "Output file (a directory with --pipeline); '-' or none: standard output");
  app.add_option("--pipeline", o.pipeline, "Comma-separated stages of one pipeline; only its last pre-rasterization stage is shifted");
  app.add_option("--depfile", o.depfile,
                 "Write the outputs' dependencies (the inputs and every #included file) as a Makefile-style depfile");

  CliOptions b;
  BuildCommandOptions buildOptions;
  auto* build = app.add_subcommand(
      "build", "Convert a whole shader tree (stages grouped into pipelines by base name) or a scene manifest");
  addConversionOptions(*build, b);
  addBuildOptions(*build, buildOptions);

  CliOptions v;
  VerifyCommandOptions verifyOptions;
  auto* verify = app.add_subcommand(
      "verify", "Run the original and the stereo shader on the CPU Vulkan driver (lavapipe) and check the shift");
  addConversionOptions(*verify, v);
  verify->add_option("input", v.inputs, "Shader, or the stages of one pipeline (only pre-rasterization stages run)");
  verify->add_option("--separation", verifyOptions.separation, "Separation used for the check")->capture_default_str();
  verify->add_option("--convergence", verifyOptions.convergence, "Convergence used for the check")->capture_default_str();
  verify->add_flag("--json", verifyOptions.json, "Machine-readable result");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  if (*verify) {
    if (auto error = finishOptions(v)) {
      std::cerr << "stereoshift: error: " << *error << "\n";
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

  if (*build) {
    if (auto error = finishOptions(b)) {
      std::cerr << "stereoshift: error: " << *error << "\n";
      printErrorSummary(1);
      return 2;
    }
    return runBuildCommand(buildOptions, b);
  }

  if (auto error = finishOptions(o)) {
    std::cerr << "stereoshift: error: " << *error << "\n";
    printErrorSummary(1);
    return 2;
  }
  std::vector<std::string> paths = o.pipeline.empty() ? o.inputs : splitCommas(o.pipeline);
  if (!o.pipeline.empty()) paths.insert(paths.end(), o.inputs.begin(), o.inputs.end());
  if (paths.empty()) {
    std::cerr << "stereoshift: error: no input file (see --help)\n";
    return 2;
  }
  if (paths.size() > 1 && o.pipeline.empty()) {
    std::cerr << "stereoshift: error: several inputs need --pipeline (or use 'stereoshift build')\n";
    return 2;
  }
  // The conversion runs in a forked child: a crash in the front end (glslang overflows its stack on
  // some inputs) becomes a clear error instead of a core dump. STEREOSHIFT_NO_FORK=1 keeps it in
  // process, for a debugger.
  auto run = [&]() -> int {
    std::vector<SourceFile> sources;
    int readErrors = readSources(paths, &sources, std::cerr);
    if (readErrors) {
      printErrorSummary(readErrors);
      return 1;
    }
    nlohmann::json reports = nlohmann::json::array();
    int errors = convert(sources, o,
                         [&](size_t i, const TranspileResult&) {
                           if (sources.size() == 1) return o.output;
                           if (o.output.empty() || o.output == "-") return std::string("-");
                           return (fs::path(o.output) / fs::path(sources[i].path).filename()).string();
                         },
                         reports, std::cerr);
    writeReport(o.reportPath, sources.size() == 1 && !reports.empty() ? reports[0] : reports);
    if (!errors && !o.depfile.empty()) {
      std::vector<std::string> targets, dependencies;
      for (const auto& r : reports)
        if (r.contains("output_file")) targets.push_back(r["output_file"].get<std::string>());
      for (const auto& s : sources) dependencies.push_back(s.path);
      for (const auto& r : reports)
        for (const auto& inc : r.value("included_files", nlohmann::json::array())) dependencies.push_back(inc.get<std::string>());
      std::string error;
      if (targets.empty()) {
        std::cerr << "stereoshift: error: --depfile needs an output file (-o)\n";
        ++errors;
      } else if (!writeAtomically(o.depfile, makeDepfile(targets, dependencies), &error)) {
        std::cerr << o.depfile << ": error: " << error << "\n";
        ++errors;
      }
    }
    printErrorSummary(errors);
    return errors ? 1 : 0;
  };
  if (const char* noFork = std::getenv("STEREOSHIFT_NO_FORK"); noFork && *noFork && std::string(noFork) != "0") return run();
  TaskOutcome outcome = runIsolatedOnce(
      [&] {
        int status = run();
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        return std::to_string(status);
      },
      0);
  if (outcome.completed) return std::atoi(outcome.payload.c_str());
  std::cerr << paths.front() << ": error: stereoshift " << outcome.failure
            << " while converting this shader; no output was written\n";
  printErrorSummary(1);
  return 1;
}
