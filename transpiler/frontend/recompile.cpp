// The re-compile checks (see front_end.h): this turns emitted GLSL or HLSL text into a yes or no from
// glslang, with its errors, under the conversion's environment (`--verify`, the splices' checks).
#include "transpiler/frontend/front_end.h"

#include "core/crash_phase.h"
#include "transpiler/frontend/glslang_invocation.h"
#include "transpiler/frontend/glslang_log.h"
#include "transpiler/frontend/include_resolver.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <optional>

namespace stereoshift {

bool verifyCompiles(const std::string& text, SourceLanguage language, Stage stage, const std::string& entryPoint,
                    bool vulkanSemantics, const std::string& displayName, Diagnostics& diags,
                    const FrontEndOptions* environment, const std::string& includeFrom) {
  ensureGlslangInitialized();
  glslang::TShader shader(toGlslang(stage));
  // glslang ends its input at a NUL byte, even in a comment: the compiler's copy has spaces there.
  const std::string given = source::blankNuls(text);
  const char* strings[] = {given.c_str()};
  const char* names[] = {displayName.c_str()};
  const int lengths[] = {static_cast<int>(given.size())};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  int messages = configureEnvironment(shader, stage, language, vulkanSemantics ? Client::Vulkan : Client::AstOnly,
                                      entryPoint, environment);
  // OpenGL GLSL/ESSL is checked as the driver would see it: AST only, the original dialect's rules.
  // A text spliced into the original (`includeFrom`: the input's path) still names the input's
  // #include files and macros: they resolve as they did for the input, with the same -D and -I.
  std::string preamble;
  if (!includeFrom.empty() && environment) {
    preamble = buildPreamble(environment->defines, language == SourceLanguage::Glsl);
    shader.setPreamble(preamble.c_str());
  }
  glslang::TShader::ForbidIncluder noIncludes;
  std::optional<RestrictedIncluder> includer;
  if (!includeFrom.empty())
    includer.emplace(includeFrom, includeSearchPath(includeFrom, environment ? environment->includeDirs
                                                                            : std::vector<std::string>{}),
                     text.size());
  glslang::TShader::Includer& includes = includer ? static_cast<glslang::TShader::Includer&>(*includer) : noIncludes;
  ScopedCrashPhase phase(kRecompilePhase);
  bool parsed = shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages), includes);
  return linkParsedShader(shader, parsed, messages, displayName, text, diags);
}

bool linkParsedShader(glslang::TShader& shader, bool parsed, int messages, const std::string& displayName,
                      const std::string& text, Diagnostics& diags) {
  bool ok = parsed;
  if (ok) {
    glslang::TProgram program;
    program.addShader(&shader);
    ok = program.link(static_cast<EShMessages>(messages));
    if (!ok) parseGlslangLog(program.getInfoLog(), displayName, {{displayName, text}}, diags);
  } else {
    parseGlslangLog(shader.getInfoLog(), displayName, {{displayName, text}}, diags);
  }
  if (!ok && !diags.hasErrors()) diags.error(displayName, "emitted shader does not compile");
  return ok;
}

}  // namespace stereoshift
