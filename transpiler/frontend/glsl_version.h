// The `#version` line of GLSL text: this turns a shader's text into the version and profile it
// declares (or GLSL's default when it declares none), read through the lexer so that a `#version`
// inside a comment is none. The legacy-dialect decision (legacy_glsl.h), the front end's choice of
// glslang client and `build`'s dialect grouping all start from it.
#pragma once

#include <cstddef>
#include <string>

namespace stereoshift {

// The first `#version N [es|core|compatibility]` directive of GLSL `text`. Total: any text gives an
// answer. A directive whose number is garbled (`3x0`), missing, too large for an int or not a GLSL
// version gives version 0 and says so in `problem`.
struct VersionLine {
  int version = 110;  // GLSL's default without #version
  bool es = false;
  bool compatibility = false;  // `#version N compatibility`
  size_t begin = std::string::npos, end = std::string::npos;  // span of the directive's text
  std::string problem;                        // empty: the directive (or its absence) is fine
  size_t problemAt = std::string::npos;       // offset in `text` the problem is reported at
};
VersionLine findVersion(const std::string& text);

}  // namespace stereoshift
