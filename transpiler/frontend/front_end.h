// Front end: GLSL (desktop, ES, Vulkan) and HLSL through glslang to SPIR-V; SPIR-V binaries as is.
// compileToSpirv (front_end.cpp) decides stage, language and dialect and makes the glslang attempts
// (glslang_invocation.h) over the #include rules of include_resolver.h; verifyCompiles
// (recompile.cpp) checks emitted text. findVersion (glsl_version.h) reads the #version line.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "transpiler/frontend/front_end_options.h"
#include "transpiler/frontend/glsl_version.h"
#include "transpiler/source/stage_rules.h"

#include <set>
#include <string>
#include <vector>

namespace glslang {
class TShader;
}  // namespace glslang

namespace stereoshift {

struct FrontEndResult {
  bool ok = false;
  std::vector<uint32_t> spirv;
  SourceInfo info;
  std::vector<std::string> includedFiles;
  std::string dialectReason;  // GLSL without #version or below 330: why this dialect (legacy_glsl.h)
  // GLSL: glslang itself refused the text (after the source limits, the #version line and the
  // legacy translation passed), so its errors may be its own gaps rather than the shader's.
  bool glslangRejected = false;
};

// Parses `input` into SPIR-V. Errors go to `diags` in file:line:col form. `stage`: the stage the
// driver decided for it (decideStage), when it did; else the front end decides it.
FrontEndResult compileToSpirv(const SourceFile& input, const FrontEndOptions& options, Diagnostics& diags,
                              const StageDecision* stage = nullptr);

// Re-compiles emitted GLSL/HLSL text to check that it is valid (`--verify`); `environment` (when
// given) carries the conversion's --target-env / --target-spv, so a subgroup shader checks under them.
bool verifyCompiles(const std::string& text, SourceLanguage language, Stage stage, const std::string& entryPoint,
                    bool vulkanSemantics, const std::string& displayName, Diagnostics& diags,
                    const FrontEndOptions* environment = nullptr, const std::string& includeFrom = "");

// glslang's process-wide initialisation, done once.
void ensureGlslangInitialized();

// The tail of every re-compile (verifyCompiles, verifyLegacyCompiles): links the shader, parsed or
// not (`parsed`: what TShader::parse returned), alone and turns glslang's log into diagnostics on
// `displayName`; a failure without a log line still says that the emitted shader does not compile.
bool linkParsedShader(glslang::TShader& shader, bool parsed, int messages, const std::string& displayName,
                      const std::string& text, Diagnostics& diags);

}  // namespace stereoshift
