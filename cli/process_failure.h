// The words for a conversion whose process did not come back (crashed, killed at the time limit),
// shared by the single-shader command and `build`: which part of the tool it was in (the phase the
// worker published, core/crash_phase.h), and the input construct known to trigger a crash there
// where the text shows one. A crash in the front end is a crash on this input, said as such.
#pragma once

#include "cli/worker_pool.h"
#include "transpiler/transpile_options.h"

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

// Whether the task's process died inside glslang's parser.
bool crashedInGlslang(const TaskOutcome& outcome);

// The crash ladder: a conversion whose process died (a third-party library crashed on what the
// shader made of it) is tried again with what it died in left out, one rung at a time, so no crash
// loses a shader that a later rung can take:
//   1. died in glslang's parser: no analysis; the text-only shift (transpiler/text_only_shift.h)
//      takes the stage where the text allows (decompiled HLSL, GLSL glslang reads too narrowly);
//   2. died in the analyses' folded copy (SPIRV-Tools' optimizer): the analyses without it;
//   3. died after the front end in anything else (the back end, the re-compile check, the folded
//      copy again): no analysis, the text-only shift as in 1.
// `options` becomes the next attempt's and `rung` says what it does differently; false when no rung
// is left (not a crash, or every rung taken), or --require-analysis forbids the text-only rungs.
bool climbCrashLadder(const TaskOutcome& outcome, TranspileOptions& options, std::string* rung);

// The words for one climbed rung: "stereoshift crashed (signal 11, SIGSEGV) in <phase>".
std::string crashWords(const TaskOutcome& outcome);

// The messages of a rung that ended with errors, said after the crash (which stays the error): each
// error a note (it says why the rung could not take the shader: a broken text, a refusal), the lines
// that only restate the crash and warnings dropped, notes kept.
std::string rungMessagesAsNotes(const std::string& messages);

}  // namespace stereoshift
