// The list of the front end's dialects (see dialect.h).
#include "transpiler/frontend/dialect.h"

#include "transpiler/frontend/glsl_lift.h"
#include "transpiler/frontend/hlsl_lift.h"

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
    compileHlslDialect(input, options, stage, decided, result, diags);
  }
};

class GlslDialect final : public FrontEndDialect {
 public:
  const char* name() const override { return "glsl"; }
  SourceLanguage language() const override { return SourceLanguage::Glsl; }
  std::string liftForAnalysis(const std::string& text, std::string* what) const override {
    LiftedGlsl copy = liftGlsl(text);
    if (what) *what = copy.lifted ? copy.what : std::string();
    return copy.lifted ? copy.text : text;
  }
  void compile(const SourceFile& input, const FrontEndOptions& options, Stage stage, const LanguageDecision& decided,
               FrontEndResult& result, Diagnostics& diags) const override {
    compileGlslDialect(input, options, stage, decided, result, diags);
  }
};

}  // namespace

const std::vector<std::unique_ptr<FrontEndDialect>>& frontEndDialects() {
  static const std::vector<std::unique_ptr<FrontEndDialect>> dialects = [] {
    std::vector<std::unique_ptr<FrontEndDialect>> list;
    list.push_back(std::make_unique<HlslDialect>());
    list.push_back(std::make_unique<GlslDialect>());
    return list;
  }();
  return dialects;
}

const FrontEndDialect& dialectOf(SourceLanguage language) {
  for (const auto& dialect : frontEndDialects())
    if (dialect->language() == language) return *dialect;
  return *frontEndDialects().back();  // SPIR-V never reaches the front end's parse; GLSL is the default
}

// What the front end decided about the input, in the result whether or not it compiles.
void recordFrontEndDecisions(FrontEndResult& result, Stage stage, const LanguageDecision& decided) {
  result.info.language = decided.language;
  result.info.languageSource = decided.source;
  result.info.languageReason = decided.reason;
  result.info.stage = stage;
}

}  // namespace stereoshift
