// `stereoshift reproject`: turns command-line options into the depth-reprojection pass's shaders
// (transpiler/reproject/reproject_shaders.h) for each --target, written into one directory with a
// JSON report, all of them or none.
#pragma once

#include "cli/conversion_options.h"  // MessageOptions
#include "transpiler/reproject/reproject_shaders.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}  // namespace CLI

namespace stereoshift {

// The option strings as given; every value is checked by runReprojectCommand (an error there is
// "stereoshift: error: ..." and exit status 1).
struct ReprojectCliOptions {
  MessageOptions messages;
  std::string outputDir, reportPath;
  std::vector<std::string> targets;
  std::string targetVersion;
  std::string eyeSource = "auto", set, binding, hlslRegister, specIdBase = "100";
  std::string blockName = "StereoParams", instanceName = "stereo";
  std::string sourceEye = "left";
  std::string depth = "zero-to-one", nearPlane = "0.1", farPlane = "inf", depthCoefficients;
  bool reversedZ = false;
  std::string samples = "8", searchNear = "0.5", refine = "bisection", refineSteps = "3";
  std::string colour = "nearest", fill = "background";
  bool mask = false;
  std::string colourBinding = "0", depthBinding = "1";
};

// Registers the `reproject` subcommand and its options on `app`.
CLI::App* addReprojectCommand(CLI::App& app, ReprojectCliOptions& o);

// The option strings read and checked: the options every --target shares, the targets, and every
// problem ("--near 1e-40 is ..."); nothing is generated or written. A value the output could not
// hold is a problem here, never a failure of the generation (the fuzz target fuzz_reproject_options
// holds that promise).
struct ParsedReproject {
  ReprojectOptions base;
  std::vector<TargetLanguage> targets;
  std::vector<std::string> problems;
};
ParsedReproject parseReprojectOptions(const ReprojectCliOptions& o);
// Generates and writes the shaders; returns the exit status (0, or 1 after printing the errors).
int runReprojectCommand(const ReprojectCliOptions& o);

}  // namespace stereoshift
