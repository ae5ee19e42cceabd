// Legacy GLSL source splice: this turns an ESSL 100 / desktop GLSL 110-150 vertex shader into its
// stereo version in the same dialect, drop-in. The passes ran on the analysis translation
// (transpiler/frontend/legacy_glsl.h); their decisions are rendered back into the user's own text:
//
//   - every token `main` (outside comments) becomes `main_stereoshift_mono`, so nothing the
//     application binds by name (attributes, varyings, uniforms) is renamed;
//   - appended at the end of the file: the eye parameters as loose uniforms (ESSL 100 has no
//     blocks; the names --eye-source loose-uniforms uses, after clash resolution) and a new `main`
//     that calls the mono one, then shifts gl_Position under the cutoff, then gives the outputs that
//     are exact copies of the clip position (halo) the shifted value.
//
// The shift is the ShiftSpec's (passes/shift_emitter.h): `x + (eyeSign*separation)*(w - convergence)`
// under `eyeSign != 0 && |w - 1| > epsilon && w finite` (or `w != 1`, or no cutoff), as a branch or a
// select. GLSL 1xx has neither `precise` nor `fma` nor (below 130) `isinf`: the plain form is used
// and "finite" is `abs(w) <= 3.40282347e+38` (false for inf and NaN, as `!isinf(w)` with the other
// terms is). Every byte of the original stays where it was.
#pragma once

#include "passes/diagnostics.h"
#include "passes/shader.h"
#include "passes/shift_emitter.h"

#include <string>
#include <vector>

namespace stereoshift {

struct GlslSpliceOptions : ShiftSpec {
  int version = 100;
  bool es = true;
  // Outputs (as written in the source) that are exact copies of gl_Position: given the shifted value.
  std::vector<std::string> haloCopies;
};

struct GlslSpliceResult {
  bool ok = false;
  std::string text;
  std::string error;
  int line = 0, column = 0;  // where the problem is; 0: whole file
};

GlslSpliceResult spliceGlslStereo(const std::string& source, const GlslSpliceOptions& options);

// The outputs of `source` whose every assignment is `name = gl_Position;` (exact copies).
std::vector<std::string> exactPositionCopies(const std::string& source);

}  // namespace stereoshift
