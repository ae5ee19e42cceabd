// Input constructs known to crash the packaged glslang, recognised from the text, so that the
// message about a front end that died (transpiler/crash_phase.h) can say what to change.
#pragma once

#include "core/shader.h"

#include <optional>
#include <string>

namespace stereoshift {

// A construct of `text` known to crash glslang, where one can be recognised from the text: its
// 1-based line and column and what it is. nullopt when none is recognised.
struct KnownCrashTrigger {
  int line = 0, column = 0;
  std::string what;
};
std::optional<KnownCrashTrigger> knownGlslangCrashTrigger(const std::string& text, SourceLanguage language);

}  // namespace stereoshift
