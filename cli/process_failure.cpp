// See process_failure.h.
#include "cli/process_failure.h"

#include "passes/crash_phase.h"
#include "transpiler/frontend/known_crashes.h"
#include "transpiler/source/file_io.h"

namespace stereoshift {

ProcessFailureText describeProcessFailure(const TaskOutcome& outcome, const std::string& file) {
  ProcessFailureText text;
  const bool inFrontEnd = outcome.phase == kGlslangGlslPhase || outcome.phase == kGlslangHlslPhase;
  const bool crashed = outcome.failure.rfind("crashed", 0) == 0;
  if (crashed && inFrontEnd) {
    // "crashed (signal 11, SIGSEGV)" -> "... crashed on this input (signal 11, SIGSEGV)"
    text.what = outcome.phase + " crashed on this input" + outcome.failure.substr(7);
  } else if (!outcome.phase.empty()) {
    text.what = "stereoshift " + outcome.failure + " in " + outcome.phase;
  } else {
    text.what = "stereoshift " + outcome.failure;
  }
  if (crashed && outcome.phase == kGlslangHlslPhase && !file.empty() && file != "-") {
    std::string contents;
    if (readFile(file, &contents))
      if (auto trigger = knownGlslangCrashTrigger(contents, SourceLanguage::Hlsl))
        text.notes.push_back(file + ":" + std::to_string(trigger->line) + ":" + std::to_string(trigger->column) +
                             ": note: " + trigger->what);
  }
  return text;
}

}  // namespace stereoshift
