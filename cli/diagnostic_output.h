// How every command ends its messages: the diagnostics printed as they are formatted, and the
// clang-style summary "N errors generated." on standard error.
#pragma once

#include "transpiler/stereoshift.h"  // Diagnostics

#include <ostream>

namespace stereoshift {

// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log);
// "N errors generated." on standard error when N > 0.
void printErrorSummary(int errors);

}  // namespace stereoshift
