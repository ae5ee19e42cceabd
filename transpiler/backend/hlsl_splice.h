// HLSL source splice: stereo injection for HLSL geometry and domain shaders without SPIR-V.
//
// The Debian SPIRV-Cross cannot re-emit HLSL geometry/hull/domain shaders, so for those stages the
// original HLSL text is kept and the clip-space shift is spliced around it:
//
//   geometry: a cbuffer and a helper `T stereoshift_shift_T(T v)` (T = the stream element struct)
//             are inserted before the first function that appends to a stream, and every
//             `stream.Append(expr)` becomes `stream.Append(stereoshift_shift_T(expr))`.
//   domain:   the entry point is renamed `<entry>_stereoshift_mono` (its attributes are moved, left
//             behind as a comment), and a wrapper with the original attributes, return type,
//             parameter list and return semantic is appended after it; the wrapper calls the mono
//             function and shifts the SV_Position output (return value, struct member or `out`
//             parameter).
//
// The shift is the ShiftSpec's (passes/shift_emitter.h), the same description the SPIR-V route
// emits: `x' = x + (eyeSign * separation) * (w - convergence)` under its cutoff, as a branch or a
// select, plain, fused (`mad`) or compensated, `precise` or not. Everything outside the inserted
// text and the rewritten tokens is preserved byte for byte; inserted text starts on its own line
// and uses the file's line endings.
//
// The pieces (transpiler/backend/hlsl_splice/): the scanner (tokens, comments, strings,
// directives), the top-level parser (functions, structs, attributes), the edit buffer (insertions
// by offset), the shift's text rendering and the geometry and domain rewriters. The scanner
// understands comments, string literals, preprocessor lines (not macro expansion, except
// `#define`s whose body calls `.Append(`), balanced brackets and template argument lists; it is
// not a full HLSL parser.
#pragma once

#include "passes/shift_emitter.h"

#include <cstdint>
#include <string>

namespace stereoshift {

// Where the shift goes, and the shift itself (the ShiftSpec it extends: cutoff, epsilon, form,
// fused, compensated, precise and the eye parameter names).
struct HlslSpliceOptions : ShiftSpec {
  using Cutoff = CutoffMode;  // Epsilon: abs(p.w - 1.0f) > epsilon; Exact: p.w != 1.0f; None: always
  std::string entryPoint;  // e.g. "GSMain", "DSMain", "main"
  bool geometry = true;    // true: geometry shader; false: domain shader (tessellation evaluation)
  std::string cbufferName = "StereoParams";
  uint32_t cbufferRegister = 0;  // register(b<N>); an error if the source already uses b<N> in space0
  // The epsilon is printed with 9 significant digits (round-trips a float); `precise` computes the
  // shifted x into a `precise float` temporary.
};

struct HlslSpliceResult {
  bool ok = false;
  std::string text;   // the stereo HLSL (ok == true)
  std::string error;  // what went wrong (ok == false)
  int line = 0;       // 1-based location of the problem; 0: no location (whole file)
  int column = 0;     // 1-based byte column; 0: unknown
  int sites = 0;      // number of shifted outputs: Append calls (geometry) or entry outputs (domain)
};

HlslSpliceResult spliceHlslStereo(const std::string& source, const HlslSpliceOptions& options);

}  // namespace stereoshift
