// A real GLSL compiler's word: this turns GLSL text into the verdict of Mesa's OpenGL driver on it
// (compiled, refused with its errors at file:line:col, or no verdict), for the routes that say yes
// where glslang did not (the text-only shift, the unanalysed copy, the lifted copy's splice): those
// are taken only where Mesa compiles the original, and their output must compile in Mesa too.
//
// Mesa is loaded at run time, never linked: libEGL.so.1 (Debian's libegl1 with libegl-mesa0) is
// opened with dlopen, a surfaceless display (EGL_MESA_platform_surfaceless) gives an OpenGL 4.5
// compatibility-profile context on llvmpipe (Debian's libgl1-mesa-dri; LIBGL_ALWAYS_SOFTWARE is set
// so every machine gives the same answer), and the shader is compiled with glCompileShader, not
// linked: a unit of a stage linked from several compiles alone. That one context takes every GLSL
// version Mesa has (1.10 ... 4.50, 1.00 ES ... 3.20 ES); a version it has not (4.60) is no verdict.
// The display and context are made once per process and kept.
//
// STEREOSHIFT_EGL_LIBRARY names another libEGL to open ("none": none at all, as on a machine
// without Mesa).
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"

#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

struct MesaVerdict {
  enum class Kind { Compiled, Refused, Unavailable };
  Kind kind = Kind::Unavailable;
  // Refused: Mesa's errors, each at the file's line and column (the info log's `0:L(C): error: ...`).
  std::vector<Diagnostic> errors;
  // Unavailable: why there is no verdict (no libEGL, no surfaceless display, a version Mesa lacks).
  std::string why;
  std::string driver;  // "Mesa 22.3.6 (llvmpipe (LLVM 15.0.6, 256 bits))" once a context exists
  // Text without #version: the version it was compiled at ("330", "300 es"); empty otherwise.
  std::string version;
};

// Mesa's verdict on `text` as a shader of `stage`, its messages naming `file`. `versionIfNone`: the
// version a loader prepends to text without a #version line (the lines keep their numbers), tried
// first; then such text is tried at each version Mesa has, from GLSL's default 110 up (an engine or
// a test runner prepends the one it needs), and compiled at the first that takes it; refused with
// the errors of the first version tried when none does.
MesaVerdict compileWithMesa(const std::string& text, Stage stage, const std::string& file,
                            std::optional<std::string> versionIfNone = std::nullopt);

// What to install for a verdict (Debian's packages), for the messages of the routes that need one.
constexpr const char* kMesaPackages = "libegl1, libegl-mesa0 and libgl1-mesa-dri";

}  // namespace stereoshift
