// The words for a conversion whose process did not come back (crashed, killed at the time limit),
// shared by the single-shader command and `build`: which part of the tool it was in (the phase the
// worker published, passes/crash_phase.h), and the input construct known to trigger a crash there
// where the text shows one. A crash in the front end is a crash on this input, said as such.
#pragma once

#include "cli/worker_pool.h"

#include <string>
#include <vector>

namespace stereoshift {

struct ProcessFailureText {
  std::string what;   // "the front end (glslang, parsing HLSL) crashed on this input (signal 11, SIGSEGV)"
  std::vector<std::string> notes;  // "file:line:col: note: ..." lines, each without its newline
};

// `outcome` is a task that did not complete; `files` the shaders it converted (read again for the
// known-trigger check; "-" is none).
ProcessFailureText describeProcessFailure(const TaskOutcome& outcome, const std::vector<std::string>& files);

// Whether the task's process died inside glslang's parser: then the conversion is worth one more
// attempt without glslang, for the text-only shift (transpiler/text_only_shift.h).
bool crashedInGlslang(const TaskOutcome& outcome);

}  // namespace stereoshift
