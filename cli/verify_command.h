// `stereoshift verify`: runs the original and the transpiled shader on the CPU Vulkan driver, or,
// for D3D shader assembly, on the assembly interpreter (transpiler/d3dasm/asm_verify.h).
#pragma once

#include "transpiler/stereoshift.h"

#include <vector>

namespace stereoshift {

struct VerifyCommandOptions {
  float separation = 0.065f;
  float convergence = 3.0f;
  bool json = false;
};

// Prints a summary (or JSON) and returns the exit status: 0 within bounds, 1 otherwise.
int runVerifyCommand(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                     const VerifyCommandOptions& verify);

}  // namespace stereoshift
