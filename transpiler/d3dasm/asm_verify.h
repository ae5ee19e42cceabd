// The execution check of the assembly route: this turns an original vertex-shader dump and its
// converted text into a verdict, by running both on the interpreter (asm_interpreter.h) with the
// same seeded random inputs and comparing every output bit for bit, except the position's x in a
// stereo run, which is compared with the exact stereo reference x + s*(w - c) computed in double
// from the original's own x and w. No GPU runs D3D bytecode here; the interpreter is the GPU.
#pragma once

#include "core/shift_spec.h"
#include "transpiler/d3dasm/asm_halo.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift::d3dasm {

struct AsmVerifyOptions {
  int samples = 4096;              // input sets; each runs mono once and both eyes
  uint64_t seed = 0x5733e05eedULL; // the same seed gives the same inputs, run after run
  CutoffMode cutoff = CutoffMode::Epsilon;  // the conversion's cutoff (its ShiftSpec)
  float cutoffEpsilon = 1e-5f;     // 0: w != 1 exactly
  // Explicit values for the first declared input register instead of random ones (set k takes
  // entry k modulo the list), so a stress table reaches the guard with the w values it chose.
  std::vector<std::array<float, 4>> firstInputValues;
  // The output lanes the conversion moved with x (asm_halo.h): a copy must carry the converted x bit
  // for bit, another lane the original's value plus coefficient * (x + s*(w - c) - x), within the
  // bound checkMovedLane derives; where x is not shifted, the original's bits.
  std::vector<AsmMovedLane> movedLanes;
  // --corrections-only: the conversion leaves the position to the driver's shift, so the position
  // must be the original's bit for bit, and a copy of x carries the shifted x on its own (checked
  // against the exact reference as x is).
  bool positionLeftToDriver = false;
};

struct AsmVerifyResult {
  bool ran = false;                // both texts decoded and ran: the figures below mean something
  bool ok = false;                 // ran and every check passed
  std::string error;               // !ran: why (the line of the text the interpreter refused)
  bool nothingToVerify = false;    // the original declares no position output
  std::string positionRegister;    // "o0"
  int samples = 0;                 // input sets run (runaway ones excluded)
  int runaway = 0;                 // input sets where the original hit the instruction limit
  int monoRuns = 0, monoMismatches = 0;            // separation 0 (+0 and -0): every output the original's
  int stereoRuns = 0;                              // one per eye per sample
  int otherOutputMismatches = 0;                   // outputs other than the position changed
  int positionYzwMismatches = 0;                   // the position's y, z or w changed
  int cutoffRuns = 0, cutoffMismatches = 0;        // stereo runs the cutoff keeps mono: x bit for bit
  int shiftedRuns = 0, shiftedFailures = 0;        // stereo runs shifted: x within the bound
  int samplesWithWOne = 0;                         // samples whose original position w is exactly 1
  double worstError = 0, worstBound = 0, worstRatio = 0;  // the shifted run nearest its bound
  int movedLaneRuns = 0, movedLaneFailures = 0;    // moved lanes compared (one per lane per stereo run)
  double worstMovedLaneRatio = 0;                  // the moved lane nearest its bound: error / bound
  std::string firstFailure;                        // the first failing run: which check, its inputs
};

AsmVerifyResult verifyAssemblyConversion(const std::string& originalText, const std::string& convertedText,
                                         const AsmVerifyOptions& options);

}  // namespace stereoshift::d3dasm
