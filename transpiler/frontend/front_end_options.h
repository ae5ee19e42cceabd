// The options the front end reads: the stage and language when the file does not say, the SPIR-V
// environment glslang parses for, the HLSL entry point, defines and include directories.
#pragma once

#include "core/shader.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

struct FrontEndOptions {
  std::optional<Stage> stage;        // -S; default: decideStage (file name, #pragma shader_stage)
  // --stage-ext / the manifest's [stages]: more stage extensions (lower case, no dot: "vp" -> vert).
  std::map<std::string, Stage> stageExtensions;
  std::optional<TargetEnv> targetEnv;  // --target-env; default: Vulkan 1.0 or OpenGL, from the source
  std::optional<int> targetSpv;        // --target-spv: the SPIR-V minor version (spv1.4 -> 4)
  std::optional<SourceLanguage> language;  // -x glsl|hlsl; default: from the file name, else the content
  std::string entryPoint;            // HLSL entry point; default `main`, then VSMain/PSMain/...
  std::vector<std::string> defines;  // NAME or NAME=VALUE
  std::vector<std::string> includeDirs;
  // Extensions the front end enables (in glslang's preamble) for its own parse of a translation:
  // what the source's dialect allows without them (ESSL 100's loop-indexed sampler arrays).
  std::vector<std::string> analysisExtensions;
  // glslang crashed on this input in an earlier attempt (the conversion child died in its parser):
  // it is not run again; the stage is refused as glslang's, for the text-only shift to take.
  bool glslangCrashed = false;
  // An earlier attempt crashed in a phase after the front end (core/crash_phase.h names it: the
  // back end, the re-compile check, the folded copy once more): the analysis is not run again and the
  // stage is refused as above, for the text-only shift to take. Empty: no such crash.
  std::string crashedAfterFrontEnd;
  // HLSL pixel shaders: the module carries glslang's OpLine per statement (its debug line info),
  // for fixes only the source text can carry, placed by line (the 3Dmigoto correction splice).
  bool sourceLines = false;
};

}  // namespace stereoshift
