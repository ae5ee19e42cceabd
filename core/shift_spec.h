// The one description of the stereo shift, `x' = x + (eyeSign*separation)*(w - convergence)` under
// its cutoff, that every printer renders in its own syntax: SPIR-V instructions
// (passes/shift_emitter.h), GLSL text (transpiler/backend/glsl_splice.h), HLSL text
// (transpiler/backend/hlsl_splice/shift_text.h) and D3D shader assembly (transpiler/d3dasm/
// asm_shift.h). The cutoff's maths is written here once (cutoffKeepsMono): what each printer's guard
// computes, and what the execution checks compare them with.
#pragma once

#include <string>

namespace stereoshift {

// Epsilon: shift when |w - 1| > epsilon; Exact: when w != 1 (the driver's rule); None: always.
enum class CutoffMode { Epsilon, Exact, None };
// How the guard is coded: an `if` around the shift, or a branch-free select.
enum class ShiftForm { Branch, Select };

// Everything that decides which arithmetic the shift is and how it is guarded.
struct ShiftSpec {
  // Epsilon: shift when |w - 1| > epsilon; Exact: when w != 1; None: always (still never in a mono
  // draw, eyeSign 0). Normalised: Epsilon only with a positive epsilon (a zero one is Exact).
  CutoffMode cutoff = CutoffMode::Epsilon;
  float epsilon = 1e-5f;
  ShiftForm form = ShiftForm::Branch;  // if around the shift, or a branch-free select
  bool fused = false;        // fma(eyeSign*separation, w - convergence, x): one rounding less
  bool compensated = false;  // error-free transformations, every operation NoContraction / precise
  bool precise = true;       // NoContraction (`precise`) on the shift, so every copy rounds alike
  // The eye parameters' names. An empty eyeSignName: the separation carries the eye's sign
  // (3Dmigoto's StereoParams, where mono is a separation of 0).
  std::string eyeSignName = "eyeSign";
  std::string separationName = "separation";
  std::string convergenceName = "convergence";
};

// The cutoff of the options (--no-cutoff, --cutoff-epsilon), normalised: a zero or negative epsilon
// is the driver's exact rule, one name for one behaviour.
CutoffMode normalisedCutoff(CutoffMode asked, float epsilon);

// Whether the guard keeps a vertex of clip-space w where it is in a stereo draw, as every printer
// computes it in fp32: |w - 1| > epsilon (Epsilon) or w != 1 (Exact) as ordered comparisons, so a
// NaN w is never shifted, and never an infinite w (0 * inf would be NaN). Without a cutoff nothing
// is kept. (A mono draw, eyeSign 0 or 3Dmigoto's separation 0, runs none of the shift either way.)
bool cutoffKeepsMono(CutoffMode cutoff, float epsilon, float w);

}  // namespace stereoshift
