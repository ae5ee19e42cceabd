// How every command ends its messages (see diagnostic_output.h).
#include "cli/diagnostic_output.h"

#include <iostream>

namespace stereoshift {

// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log) {
  log << diags.format();
  return diags.errorCount();
}

void printErrorSummary(int errors) {
  if (errors > 0) std::cerr << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
}

}  // namespace stereoshift
