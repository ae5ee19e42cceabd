// The HLSL dialect's parse (dialect.h): the entry point (-e, else as the text names it), tried on
// the text with its effect blocks blanked and the decompiler's idioms lifted.
#include "transpiler/frontend/dialect.h"

#include "transpiler/frontend/glslang_invocation.h"
#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/frontend/hlsl_lift.h"

#include <algorithm>
#include <set>

namespace stereoshift {

namespace {

class HlslDialect final : public FrontEndDialect {
 public:
  const char* name() const override { return "hlsl"; }
  SourceLanguage language() const override { return SourceLanguage::Hlsl; }
  std::string liftForAnalysis(const std::string& text, std::string* what) const override {
    std::string lifted;
    std::string copy = hlslForGlslang(text, &lifted);
    if (what) *what = lifted;
    return copy;
  }
  void compile(const SourceFile& input, const FrontEndOptions& options, Stage stage, const LanguageDecision& decided,
               FrontEndResult& result, Diagnostics& diags) const override {
    std::set<std::string> functions = mentionedFunctions(input.contents);
    std::string entry = chooseHlslEntry(input.contents, functions, stage, options.entryPoint);
    // The text names its entry point, or the entry comes from an #include or a macro (`ENTRY(main)`),
    // which only glslang's preprocessor sees: then `main` and the stage's conventional name are tried
    // on the preprocessed shader (glslang links without an entry point, with a warning, when the name
    // is missing).
    std::vector<std::string> candidates = {entry};
    if (!functions.count(entry) && options.entryPoint.empty()) {
      candidates = {"main"};
      if (const char* conventional = conventionalHlslEntry(stage)) candidates.push_back(conventional);
    }
    auto entryMissing = [](const Diagnostics& d) {
      return std::any_of(d.all().begin(), d.all().end(), [](const Diagnostic& x) {
        return x.message.find("Entry point not found") != std::string::npos;
      });
    };
    // Effect files: glslang parses the HLSL once technique and state blocks are blanked out; the
    // idioms of decompiled shaders it refuses are lifted (hlsl_lift.h), for the analysis only.
    std::string lifted;
    std::string blanked = liftForAnalysis(input.contents, &lifted);
    Attempt a;
    bool found = false;
    for (const auto& candidate : candidates) {
      a = compileGlslangOnce(input, blanked, stage, SourceLanguage::Hlsl, Client::Vulkan, candidate, options);
      if (!entryMissing(a.diags)) {
        entry = candidate;
        found = true;
        break;
      }
    }
    if (!found) {
      diags.error(input.path, "entry point '" + entry + "' not found" +
                                  (options.entryPoint.empty() ? "; name it with -e <function>" : ""));
      return;
    }
    diags.append(a.diags);
    if (!a.ok) {
      // glslang's own refusal, past the source limits and the entry-point search: for decompiled text
      // it may be glslang's gap (text_only_shift.h).
      result.glslangRejected = !a.diags.all().empty() && !entryMissing(a.diags);
      return;
    }
    result.ok = true;
    result.spirv = std::move(a.spirv);
    result.info = std::move(a.info);
    recordFrontEndDecisions(result, stage, decided);
    result.info.entryPoint = entry;
    result.info.vulkan = true;
    result.info.liftedBecause = lifted;
    // Conservative: a mention in a comment only makes the injected binding skip more numbers.
    result.info.vulkanBindings = input.contents.find("vk::binding") != std::string::npos;
    result.includedFiles = std::move(a.included);
  }
};

}  // namespace

std::unique_ptr<FrontEndDialect> makeHlslDialect() { return std::make_unique<HlslDialect>(); }

}  // namespace stereoshift
