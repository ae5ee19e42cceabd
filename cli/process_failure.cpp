// See process_failure.h.
#include "cli/process_failure.h"

#include "core/crash_phase.h"
#include "transpiler/frontend/known_crashes.h"
#include "transpiler/source/file_io.h"

namespace stereoshift {

bool crashedInGlslang(const TaskOutcome& outcome) {
  return !outcome.completed && outcome.failure.rfind("crashed", 0) == 0 &&
         (outcome.phase == kGlslangGlslPhase || outcome.phase == kGlslangHlslPhase);
}

bool climbCrashLadder(const TaskOutcome& outcome, TranspileOptions& options, std::string* rung) {
  if (outcome.completed || outcome.failure.rfind("crashed", 0) != 0) return false;
  if (crashedInGlslang(outcome)) {
    if (options.glslangCrashed || options.requireAnalysis) return false;
    options.glslangCrashed = true;
    *rung = "without glslang's parser: the shift from the text alone";
    return true;
  }
  if (outcome.phase == kFoldedCopyPhase && !options.foldedCopyCrashed) {
    options.foldedCopyCrashed = true;
    *rung = "with the analyses but without their folded copy";
    return true;
  }
  if (options.glslangCrashed || !options.crashedAfterFrontEnd.empty() || options.requireAnalysis) return false;
  options.crashedAfterFrontEnd = outcome.phase.empty() ? std::string("an unmarked phase") : outcome.phase;
  *rung = "without the analysis: the shift from the text alone";
  return true;
}

std::string rungMessagesAsNotes(const std::string& messages) {
  std::string notes;
  size_t at = 0;
  while (at < messages.size()) {
    size_t end = messages.find('\n', at);
    if (end == std::string::npos) end = messages.size();
    std::string line = messages.substr(at, end - at);
    at = end + 1;
    if (line.find("was not run again") != std::string::npos || line.find(": warning: ") != std::string::npos ||
        line.find("error generated") != std::string::npos || line.find("errors generated") != std::string::npos)
      continue;
    if (size_t error = line.find(": error: "); error != std::string::npos) line.replace(error, 9, ": note: ");
    if (line.find(": note: ") != std::string::npos) notes += line + "\n";
  }
  return notes;
}

std::string crashWords(const TaskOutcome& outcome) {
  return "stereoshift " + outcome.failure + (outcome.phase.empty() ? std::string() : " in " + outcome.phase);
}

ProcessFailureText describeProcessFailure(const TaskOutcome& outcome, const std::vector<std::string>& files) {
  ProcessFailureText text;
  const bool crashed = outcome.failure.rfind("crashed", 0) == 0;
  if (crashedInGlslang(outcome)) {
    // "crashed (signal 11, SIGSEGV)" -> "... crashed on this input (signal 11, SIGSEGV)"
    text.what = outcome.phase + " crashed on this input" + outcome.failure.substr(7);
  } else if (!outcome.phase.empty()) {
    text.what = "stereoshift " + outcome.failure + " in " + outcome.phase;
  } else {
    text.what = "stereoshift " + outcome.failure;
  }
  if (!crashed || outcome.phase != kGlslangHlslPhase) return text;
  for (const auto& file : files) {
    std::string contents;
    if (file != "-" && readFile(file, &contents))
      if (auto trigger = knownGlslangCrashTrigger(contents, SourceLanguage::Hlsl))
        text.notes.push_back(file + ":" + std::to_string(trigger->line) + ":" + std::to_string(trigger->column) +
                             ": note: " + trigger->what);
  }
  return text;
}

}  // namespace stereoshift
