// Legacy GLSL: this turns ESSL 100 (WebGL1, GL ES 2.0), desktop GLSL 110-150 and the compatibility
// profile of any version into a faithful ESSL 310 / GLSL 330 (or, past 330, the shader's own core
// version) translation that glslang can make SPIR-V from, for analysis only: the passes
// read it, and the same-language output is the original text with the shift spliced in
// (transpiler/backend/glsl_splice.h). The rewrite is token by token and keeps every line of the
// user's text where it was, so glslang's diagnostics point at what the user wrote:
//
//   attribute -> in; varying -> out (vertex, geometry) / in (fragment)
//   texture2D, texture2DProj, texture2DLod(EXT), textureCube, textureCubeLod(EXT), ... -> texture,
//   textureProj, textureLod, ...; shadow2D & co. -> helpers returning vec4 as 1xx did
//   gl_FragColor, gl_FragData[n] -> declared outputs; gl_FragDepthEXT -> gl_FragDepth
//   #extension lines whose feature is core in ESSL 300 -> blanked
//   compatibility built-ins of old desktop tutorials (gl_Vertex, gl_MultiTexCoord0..7, gl_Color,
//   gl_ModelViewProjectionMatrix, gl_NormalMatrix, gl_TextureMatrix[], gl_FrontColor, gl_TexCoord[],
//   ...) -> declared inputs, uniforms and outputs named stereoshift_<name without gl_>;
//   ftransform() -> (stereoshift_ModelViewProjectionMatrix * stereoshift_Vertex)
//
// Declarations it needs go at the start of the first line of code outside any #if, so no line moves.
// A shader without #version gets one (and `#line 1`): GLSL says such a shader is 110, but one with
// ES-only hints (a precision statement, an ES extension) is WebGL1's ESSL 100 (decideLegacyDialect).
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "transpiler/frontend/front_end.h"

#include <string>
#include <vector>

namespace stereoshift {

// The dialect a GLSL text is written in, as far as the legacy route cares.
struct LegacyDialect {
  bool legacy = false;  // ESSL 100, desktop GLSL below 330 or any compatibility profile: takes this translation
  int version = 0;      // the original (or decided) version: 100, 110 ... 150, or a compatibility profile's
  bool es = false;
  bool versionWritten = false;  // false: no #version, the version was decided from the text
  std::string reason;           // why this dialect, for the report
  bool byDefault = false;       // no #version and nothing in the text chose: GLSL's default 110
};

// The dialect of `text` given its #version line (findVersion).
LegacyDialect decideLegacyDialect(const std::string& text, const VersionLine& version);

// A shader without #version is GLSL 110 or ESSL 100 by the language's rule, but much code is written
// for a loader that prepends a #version of its own (engines, three.js, piglit's shader_runner), so
// its text uses what 110 / 100 do not have (`in`/`out`, layout qualifiers, a matrix built from a
// matrix in a WebGL1 vertex shader, which needs no precision statement and so shows nothing
// ES-only). When glslang refuses such a text at the decided version, the lowest version it takes
// it at is the dialect: ESSL 100 first for a vertex or fragment shader nothing chose (byDefault),
// then desktop 120 ... 460; ESSL 300 ... 320 for one with ES hints. A version from 330 / ESSL 300
// on leaves the legacy translation (`legacy` false): the front end parses the text with that
// #version put before it, and the output stays without one. Costs one parse for a versionless
// shader, one more per version tried when the first fails.
void settleVersionlessDialect(LegacyDialect& dialect, const std::string& text, Stage stage);

struct LegacyTranslation {
  bool ok = false;
  std::string text;                   // the ESSL 310 / GLSL 330 translation
  Diagnostic error;                   // why not (ok == false), located in the user's text
  std::vector<std::string> declared;  // built-ins the translation declares (stereoshift_... names)
};

// Translates `text` (of `dialect`, for `stage`) as described above. `path` names the file in errors.
LegacyTranslation translateLegacyGlsl(const std::string& text, Stage stage, const LegacyDialect& dialect,
                                      const std::string& path);

// Compiles `text` with glslang's AST-only front end at `version` (`es`): what a GL driver would
// accept. A text without #version is read at that version. Errors go to `diags`.
bool verifyLegacyCompiles(const std::string& text, Stage stage, int version, bool es, const std::string& displayName,
                          Diagnostics& diags);

}  // namespace stereoshift
