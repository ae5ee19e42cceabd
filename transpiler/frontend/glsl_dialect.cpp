// The GLSL dialect's parse (dialect.h): the client from the #version line (desktop >= 400 and ES >=
// 310 may be Vulkan GLSL, tried first, or OpenGL GLSL with loose uniforms), ESSL 100 and desktop
// 110-150 through their legacy translation, a text without #version at the version it is of, and a
// lifted copy where glslang refuses the text as written.
#include "transpiler/frontend/dialect.h"

#include "transpiler/frontend/glsl_lift.h"
#include "transpiler/frontend/glsl_version.h"
#include "transpiler/frontend/glslang_invocation.h"
#include "transpiler/frontend/legacy_glsl.h"
#include "transpiler/source/lexer.h"

#include <algorithm>
#include <optional>

namespace stereoshift {

namespace {

// A garbled #version, said as such: glslang itself would fall back to ESSL 100 and complain that ES
// shaders for SPIR-V need version 310, which points the wrong way. (A missing one is not a problem:
// the shader is GLSL 110 or ESSL 100, see decideLegacyDialect.)
void reportVersionProblem(const SourceFile& input, const VersionLine& v, Diagnostics& diags) {
  auto [line, column] = source::lineAndColumn(input.contents, v.problemAt);
  diags.error(input.path, line, column, v.problem);
}

// The client from the #version line: desktop >= 400 and ES >= 310 may be Vulkan GLSL (tried first)
// or OpenGL GLSL with loose uniforms (the fallback); older dialects are OpenGL.
// Whether glslang's Vulkan rules refused something OpenGL GLSL may write (a uniform outside a
// block, a user varying without a location).
bool refusesOpenGLStyleForVulkan(const Diagnostics& diags) {
  const auto& all = diags.all();
  return std::any_of(all.begin(), all.end(), [](const Diagnostic& d) {
    return d.severity == Severity::Error && d.message.find("not allowed when using GLSL for Vulkan") != std::string::npos;
  });
}

class GlslDialect final : public FrontEndDialect {
 public:
  const char* name() const override { return "glsl"; }
  SourceLanguage language() const override { return SourceLanguage::Glsl; }
  std::string liftForAnalysis(const std::string& text, std::string* what) const override {
    LiftedGlsl copy = liftGlsl(text);
    if (what) *what = copy.lifted ? copy.what : std::string();
    return copy.lifted ? copy.text : text;
  }
  // The text parsed under each client in turn (Vulkan first where it may be): the first that takes
  // it, else the attempt whose errors say most about the shader.
  static std::optional<Attempt> parseUnderEachClient(const SourceFile& input, const std::string& text, Stage stage,
                                                     const std::vector<Client>& clients, const std::string& glslEntry,
                                                     const FrontEndOptions& parseOptions, bool targetEnvGiven,
                                                     FrontEndResult& result) {
    std::optional<Attempt> best;
    std::optional<Attempt> vulkanButOpenGLStyle;
    for (Client client : clients) {
      Attempt a = compileGlslangOnce(input, text, stage, SourceLanguage::Glsl, client, glslEntry, parseOptions);
      if (a.ok) {
        a.info.vulkan = client == Client::Vulkan;
        // Valid as Vulkan GLSL only through the auto-mapping, with an interface written the OpenGL
        // way: OpenGL GLSL, if OpenGL rules take it (else Vulkan after all: `set`, push constants).
        if (client == Client::Vulkan && !a.openGLStyleInterface.empty() && !targetEnvGiven) {
          result.dialectReason = "Vulkan GLSL only with locations and bindings made up: its " + a.openGLStyleInterface +
                                 ", as OpenGL code writes it, so OpenGL GLSL";
          vulkanButOpenGLStyle = std::move(a);
          continue;
        }
        best = std::move(a);
        break;
      }
      // Both refused: the fewer errors, except that a Vulkan attempt refusing the interface as
      // OpenGL writes it ("... when using GLSL for Vulkan") says nothing of the shader's real error,
      // which the OpenGL attempt then names (a double vertex input below GLSL 410, not the loose uniform).
      bool bestRefusedOpenGLStyle = best && client == Client::OpenGL && refusesOpenGLStyleForVulkan(best->diags);
      if (!best || bestRefusedOpenGLStyle || a.diags.errorCount() < best->diags.errorCount()) best = std::move(a);
    }
    if ((!best || !best->ok) && vulkanButOpenGLStyle) {
      best = std::move(vulkanButOpenGLStyle);
      result.dialectReason.clear();
    }
    return best;
  }

  void compile(const SourceFile& input, const FrontEndOptions& options, Stage stage, const LanguageDecision& decided,
               FrontEndResult& result, Diagnostics& diags) const override {
    VersionLine v = findVersion(input.contents);
    if (!v.problem.empty()) {
      reportVersionProblem(input, v, diags);
      return;
    }
    std::string text = input.contents;
    // ESSL 100 and desktop 110-150 (and no #version at all): glslang makes SPIR-V only from ESSL 310 and
    // GLSL 330 on, and asked for 1xx with a SPIR-V client it fails its own built-ins and prints them to
    // stdout. Such shaders are parsed as a faithful ESSL 310 / GLSL 330 translation instead (the
    // same-language output is the original text, see glsl_splice.h), so glslang never sees 1xx here.
    LegacyDialect dialect = decideLegacyDialect(input.contents, v);
    settleVersionlessDialect(dialect, input.contents, stage);
    bool usesCompatibilityBuiltIns = false;
    bool versionPrepended = false;
    FrontEndOptions parseOptions = options;
    if (dialect.legacy && dialect.es) {
      // ESSL 100 lets a loop index pick a sampler of an array (its Appendix A's constant-index
      // expressions); ESSL 310 only with GL_EXT_gpu_shader5 (the output keeps the original text).
      parseOptions.analysisExtensions.push_back("GL_EXT_gpu_shader5");
    }
    if (dialect.legacy) {
      LegacyTranslation translated = translateLegacyGlsl(input.contents, stage, dialect, input.path);
      if (!translated.ok) {
        diags.add(translated.error);
        return;
      }
      text = std::move(translated.text);
      usesCompatibilityBuiltIns = !translated.declared.empty();
      v.version = dialect.version;
      v.es = dialect.es;
      result.dialectReason = dialect.reason;
    } else if (!dialect.versionWritten) {
      // No #version, and the text is of a version past the legacy ones (settleVersionlessDialect):
      // parsed with that version put before it (ESSL 300 as 310, as below), its lines numbered as
      // written; the output stays without one, for the loader that prepends its own.
      v.version = dialect.version;
      v.es = dialect.es;
      const int parseVersion = v.es ? std::max(v.version, 310) : v.version;
      text = "#version " + std::to_string(parseVersion) + (v.es ? " es" : "") + "\n#line 1\n" + text;
      result.dialectReason = dialect.reason;
      versionPrepended = true;
    } else if (v.es && v.version < 310) {
      // glslang 12 refuses ES < 310 for SPIR-V; parse as 310 (same line count) and emit the original.
      text.replace(v.begin, v.end - v.begin, "#version 310 es");
    }
    std::vector<Client> clients;
    // A text without #version is never Vulkan GLSL (that needs its #version written): its loader
    // prepends an OpenGL one, so it is read with OpenGL's rules (else the eye parameters would go in
    // a `set =` block no OpenGL compiler takes).
    bool mayBeVulkan = !versionPrepended && ((!v.es && v.version >= 400) || (v.es && v.version >= 310));
    if (mayBeVulkan && options.targetEnv != TargetEnv::OpenGL45) clients.push_back(Client::Vulkan);  // --target-env opengl: GL rules only
    clients.push_back(Client::OpenGL);

    // -e NAME: the function glslang compiles as `main` (glslangValidator's --source-entrypoint).
    const std::string glslEntry = options.entryPoint.empty() ? "main" : options.entryPoint;
    std::optional<Attempt> best = parseUnderEachClient(input, text, stage, clients, glslEntry, parseOptions,
                                                       options.targetEnv.has_value(), result);
    // Refused as written: a lifted copy (glsl_lift.h) for the analysis, with OpenGL rules.
    std::string lifted;
    if (!best->ok) {
      std::string what;
      std::string copy = liftForAnalysis(text, &what);
      if (!what.empty()) {
        Attempt a = compileGlslangOnce(input, copy, stage, SourceLanguage::Glsl, Client::OpenGL, glslEntry, parseOptions);
        if (a.ok) {
          a.info.vulkan = false;
          best = std::move(a);
          lifted = what;
        }
      }
    }
    if (!best->ok) {
      result.glslangRejected = true;
      diags.append(best->diags);
      if (decided.source == LanguageSource::Content && v.begin == std::string::npos)
        diags.note(input.path, "parsed as GLSL (" + decided.reason + "); if this is HLSL, say so with -x hlsl");
      const auto& all = best->diags.all();
      if (options.entryPoint.empty() && std::any_of(all.begin(), all.end(), [](const Diagnostic& d) {
            return d.message.find("Missing entry point") != std::string::npos;
          }))
        diags.note(input.path, "no `main`: if another function is the entry point, name it with -e <function>");
      return;
    }
    diags.append(best->diags);  // warnings
    result.ok = true;
    result.spirv = std::move(best->spirv);
    result.info = std::move(best->info);
    recordFrontEndDecisions(result, stage, decided);
    result.info.version = v.version;
    result.info.es = v.es;
    result.info.compatibilityBuiltIns = usesCompatibilityBuiltIns;
    result.info.liftedBecause = lifted;
    result.info.versionPrepended = versionPrepended;
    // An extension may give the text, at a lower version than glslang reads it at, what glslang knows
    // only at a core version (uaddCarry at 400).
    if (versionPrepended && !v.es && v.version >= 400 && enablesAnExtension(input.contents))
      result.info.spliceVersionCap = 150;
    result.info.entryPoint = "main";
    result.includedFiles = std::move(best->included);
  }
};

}  // namespace

std::unique_ptr<FrontEndDialect> makeGlslDialect() { return std::make_unique<GlslDialect>(); }

}  // namespace stereoshift
