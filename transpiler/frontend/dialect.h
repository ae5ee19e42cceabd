// The front end's dialects, kept in a list as the back end's routes are: this turns "the text is
// HLSL" or "the text is GLSL" into one object that parses it to SPIR-V its own way (HLSL with its
// entry point and effect blocks blanked; GLSL by its #version, the legacy translation, Vulkan before
// OpenGL rules) and makes the copy glslang parses for the analysis where the text as written is
// refused or cannot be parsed (what the dialect lifts; the output keeps the original text). The
// language decision that picks a dialect is language_detect.h's (one scorer weighs both languages).
#pragma once

#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/language_detect.h"

#include <memory>
#include <string>
#include <vector>

namespace stereoshift {

class FrontEndDialect {
 public:
  virtual ~FrontEndDialect() = default;
  virtual const char* name() const = 0;  // "hlsl", "glsl"
  virtual SourceLanguage language() const = 0;
  // The copy of `text` glslang is given for the analysis, and what was lifted in it (`*what` empty:
  // the copy is the text). HLSL: always (effect blocks blanked, decompiler idioms lifted); GLSL: when
  // glslang refuses the text as written (line continuations, extension versions, block redeclarations).
  virtual std::string liftForAnalysis(const std::string& text, std::string* what) const = 0;
  // Parses the input (its stage and language decided) into `result`, errors into `diags`.
  virtual void compile(const SourceFile& input, const FrontEndOptions& options, Stage stage,
                       const LanguageDecision& decided, FrontEndResult& result, Diagnostics& diags) const = 0;
};

// Every dialect, and the one of a language.
const std::vector<std::unique_ptr<FrontEndDialect>>& frontEndDialects();
const FrontEndDialect& dialectOf(SourceLanguage language);

// What the front end decided about the input, in the result whether or not it compiles.
void recordFrontEndDecisions(FrontEndResult& result, Stage stage, const LanguageDecision& decided);

// The dialects, each in its own file (hlsl_dialect.cpp, glsl_dialect.cpp).
std::unique_ptr<FrontEndDialect> makeHlslDialect();
std::unique_ptr<FrontEndDialect> makeGlslDialect();

}  // namespace stereoshift
