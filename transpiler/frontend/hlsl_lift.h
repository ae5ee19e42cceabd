// HLSL text as glslang can parse it, for the analysis and the re-compile checks only (the output is
// always the original text plus the splice's edits): this turns the idioms of decompiled shaders
// that glslang's HLSL parser refuses into equivalent forms it accepts, keeping every line break so
// line numbers stay the file's. The idioms:
//   - 3Dmigoto's decompiler writes comparisons as `#define cmp -` and `r1.w = cmp(a < b);` (a negated
//     bool: 0 or -1, its all-ones mask), and glslang's parser fails on a unary minus before a
//     parenthesised comparison; the macro becomes `#define cmp(x) (0 - (x))`, the same value in
//     every context (a function-like macro keeps the precedence of the negation it replaces).
//   - System-value semantics with index 0 (`SV_POSITION0`), which glslang maps to no built-in.
//   - A swizzle of several matrix components read (`World._m00_m10_m20_m30`), which glslang types as
//     a constant integer 0 (invalid SPIR-V that crashed the optimizer): one component at a time,
//     `float4(World._m00, World._m10, World._m20, World._m30)`.
#pragma once

#include <string>

namespace stereoshift {

// `text` with the idioms replaced; `what` (when given) says which, empty when none was found.
std::string liftHlslIdioms(const std::string& text, std::string* what = nullptr);

// What glslang is given for HLSL text: effect blocks blanked (hlsl_effects.h), idioms lifted.
std::string hlslForGlslang(const std::string& text, std::string* what = nullptr);

}  // namespace stereoshift
