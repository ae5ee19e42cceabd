// The output version a single-pass mode needs (the driver raises an OpenGL GLSL output to it).
#pragma once

#include "core/shader.h"
#include "transpiler/transpile_options.h"

#include <optional>
#include <string>

namespace stereoshift {

// The lowest OpenGL GLSL version a single-pass mode needs for this stage of an OpenGL (not Vulkan,
// not ES) GLSL shader kept in GLSL, when the shader's own version is below it and no --target-version
// was given (the output is then raised to it: desktop GLSL links stages of different versions);
// nullopt otherwise, and for a shader using compatibility built-ins (SourceInfo; a raise would turn
// gl_Vertex, gl_ModelViewProjectionMatrix, ... into stereoshift_* inputs and uniforms the application
// does not set: that takes an explicit --target-version). `why` receives the reason.
std::optional<int> singlePassRaisedGlslVersion(const SourceInfo& source, const TranspileOptions& options,
                                               std::string* why);

}  // namespace stereoshift
