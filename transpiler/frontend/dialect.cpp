// The list of the front end's dialects (see dialect.h).
#include "transpiler/frontend/dialect.h"

namespace stereoshift {

const std::vector<std::unique_ptr<FrontEndDialect>>& frontEndDialects() {
  static const std::vector<std::unique_ptr<FrontEndDialect>> dialects = [] {
    std::vector<std::unique_ptr<FrontEndDialect>> list;
    list.push_back(makeHlslDialect());
    list.push_back(makeGlslDialect());
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
