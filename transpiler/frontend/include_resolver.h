// How the front end resolves #include for glslang: this turns glslang's include requests into file
// contents read only from the including file's directory and the -I directories, and refuses, with
// a reason in place of glslang's "Could not process include directive", what would make glslang run
// away: an unguarded include cycle, nesting past kMaxIncludeDepth, more than kMaxSourceBytes of
// source in all, an included file past the bracket limit (source_limits.h).
#pragma once

#include "core/diagnostics.h"

#include <glslang/Public/ShaderLang.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

// Why an #include was refused: the error to report in place of glslang's "Could not process
// include directive" at the directive, or (`ownLocation`) a located error inside the included file.
struct IncludeRefusal {
  std::string includer, header;  // the directive: the file it is in (as glslang names it) and its header
  Diagnostic replacement;
  bool ownLocation = false;
};

// Whether `text` opens (after blank lines and comments) with `#pragma once` or with `#ifndef NAME`
// then `#define NAME`: an include guard, so a nested re-inclusion adds nothing.
bool hasIncludeGuard(const std::string& text);

// Resolves #include only inside the including file's directory and the -I directories, so a
// shader tree conversion never reads outside what the user named; an include cycle without include
// guards is refused (glslang would include forever), a guarded one included as empty text.
class RestrictedIncluder : public glslang::TShader::Includer {
 public:
  RestrictedIncluder(std::string mainFile, std::vector<std::string> includeDirs, size_t mainBytes);

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* result) override;

  // The included files' names (as diagnostics name them) and texts, in the order read.
  const std::vector<std::pair<std::string, std::string>>& sources() const { return sources_; }
  const std::vector<std::string>& includedFiles() const { return included_; }
  const std::vector<IncludeRefusal>& refusals() const { return refusals_; }

 private:
  struct OpenFile {
    std::string name;  // as diagnostics name it
    std::filesystem::path identity;
    bool guarded = false;  // opens with an include guard or #pragma once
  };

  bool beginDirective(const char* header, const char* includer, size_t depth);
  IncludeResult* searchIncludeDirs(const char* header);
  void refuse(std::string message);
  IncludeResult* tryOpen(const std::filesystem::path& dir, const char* header);
  std::string describeCycle(const std::filesystem::path& nextIdentity, const std::string& nextName) const;

  std::string mainFile_;
  std::vector<std::string> includeDirs_;
  size_t totalBytes_ = 0;
  std::vector<OpenFile> chain_;  // the shader, then the include stack
  std::string currentHeader_, currentIncluder_;
  size_t currentDepth_ = 0;
  bool refusedThisDirective_ = false;
  std::vector<IncludeRefusal> refusals_;
  std::vector<std::pair<std::string, std::string>> sources_;
  std::vector<std::string> included_;
};

// glslang's errors with each refused #include's "Could not process include directive" replaced by
// the reason it was refused.
Diagnostics explainRefusedIncludes(const Diagnostics& raw, const std::vector<IncludeRefusal>& refusals);

}  // namespace stereoshift
