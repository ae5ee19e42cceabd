// The lifted copy: this turns OpenGL GLSL that glslang refuses as written, though drivers compile
// it, into a copy glslang accepts, for the analysis only (the output stays the original text plus
// the splice's marked edits, glsl_splice.h):
//   - line continuations (a backslash at a line's end) joined, the lost line breaks put back after
//     the logical line so every later line keeps its number;
//   - comments or blank lines before the #version line (ESSL wants it first) moved after it;
//   - the #version raised to the lowest core version that has what the #extension lines enable
//     (GL_ARB_gpu_shader5 -> 400, GL_ARB_arrays_of_arrays -> 430, ...): glslang knows some
//     extensions' built-ins and syntax only at the version they became core in; the #extension
//     lines of what is core at the raised version blanked (glslang does not know some of them by
//     name, GL_ARB_arrays_of_arrays, and `require` of an unknown one is an error);
//   - a built-in block redeclaration (`out gl_PerVertex { ... };`) raises it to 410, the first
//     version glslang takes one at.
// The version raise is for desktop GLSL only; the profile word of the #version line is kept.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace stereoshift {

struct LiftedGlsl {
  bool lifted = false;  // the copy differs from the text
  std::string text;
  std::string what;     // "line continuations joined", "#version 150 raised to 400 for GL_ARB_gpu_shader5", ...
};

LiftedGlsl liftGlsl(const std::string& text);

// Whether `text` has an #extension line that enables something (not `disable`, not glslang's own
// #include extension): what it enables glslang may know only at a later version, or not at all.
bool enablesAnExtension(const std::string& text);

// The OpenGL core version an ARB / EXT extension's GLSL functionality became part of; none for an
// extension that never did (or that this table does not know).
std::optional<int> coreVersionOf(std::string_view extension);

}  // namespace stereoshift
