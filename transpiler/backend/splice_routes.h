// The source-splice routes: the original text with the edits the passes decided spliced into it.
//   HLSL (vertex, geometry, domain kept as HLSL): hlsl_splice.h renders the shift; every vertex
//     entry point of the file is shifted (the driver converts each on its own first), every other
//     one kept as written.
//   legacy GLSL (ESSL 100, desktop 110-150 vertex shaders kept in their dialect): glsl_splice.h.
//   GLSL (every other vertex, tessellation-evaluation and geometry shader kept in its dialect):
//     glsl_splice.h too, with the eye parameters as the passes declared them.
// What the text cannot carry is refused (HLSL geometry / domain) or left to SPIRV-Cross's re-emit
// with a note saying why (HLSL vertex), or said as a warning and recorded (legacy GLSL); the GLSL splice leaves to the re-emit
// with a note whatever it cannot carry.
#pragma once

#include "transpiler/backend/route.h"

#include <memory>
#include <string>

namespace stereoshift {

std::unique_ptr<BackEndRoute> createHlslSpliceRoute();
// HLSL pixel shaders kept as HLSL whose corrections only the text carries (the deferred pass's
// text fixes, with 3Dmigoto's StereoParams): hlsl_pixel_splice_route.cpp.
std::unique_ptr<BackEndRoute> createHlslPixelSpliceRoute();
// An engine's HLSL pixel shader whose unprojection the deferred pass fixed: the fix in its own text.
std::unique_ptr<BackEndRoute> createHlslUnprojectionSpliceRoute();
std::unique_ptr<BackEndRoute> createLegacyGlslRoute();
std::unique_ptr<BackEndRoute> createGlslSpliceRoute();

// Whether the HLSL splice takes a shader of `info` emitted as `target`.
bool takesHlslSpliceRoute(const SourceInfo& info, TargetLanguage target);
// Whether the legacy GLSL splice takes a shader of `info` emitted as `target` (no --target-version,
// no --force-reemit). Its passes declare the eye parameters as loose uniforms (GLSL below 140 and
// ESSL 100 have no uniform blocks).
bool takesLegacyGlslRoute(const SourceInfo& info, TargetLanguage target, const BackEndOptions& options);
// Whether the shader is in a dialect glslang parses only through the analysis translation
// (transpiler/frontend/legacy_glsl.h): ESSL 100, desktop GLSL below 330.
bool isLegacyGlslDialect(const SourceInfo& info);
// The source's name of a name in that translation (stereoshift_TexCoord -> gl_TexCoord).
std::string sourceName(const std::string& translated);
// Whether the GLSL splice may take a shader of `info` emitted as `target`: a GLSL vertex,
// tessellation-evaluation or geometry stage kept in its own dialect and version.
bool takesGlslSpliceRoute(const SourceInfo& info, TargetLanguage target, const BackEndOptions& options);

}  // namespace stereoshift
