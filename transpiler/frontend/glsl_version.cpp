// This turns GLSL text into its #version line (see glsl_version.h). The lexer finds the directive
// and stops there (most shaders open with it); its operands are read from the directive's tokens. It
// never throws: the build parent runs it on every shader of a tree.
#include "transpiler/frontend/glsl_version.h"

#include "transpiler/source/lexer.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace stereoshift {

namespace {

// The versions a `#version` line may name (GLSL 1.10-4.60, ESSL 1.00-3.20).
bool isGlslVersion(long long n) {
  for (int known : {100, 110, 120, 130, 140, 150, 300, 310, 320, 330, 400, 410, 420, 430, 440, 450, 460})
    if (n == known) return true;
  return false;
}

// The directive as written from `directive` up to the first blank or comment at or after `from`, for
// a message (at most 48 bytes).
std::string quoted(const std::string& text, size_t directive, size_t from) {
  size_t end = from;
  while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
         text.compare(end, 2, "//") != 0 && text.compare(end, 2, "/*") != 0)
    ++end;
  return text.substr(directive, std::min<size_t>(end - directive, 48));
}

}  // namespace

VersionLine findVersion(const std::string& text) {
  VersionLine v;
  source::Lexer lexer(text);
  source::Token t;
  bool found = false;
  while (!found && lexer.next(t))
    found = t.kind == source::TokenKind::Directive && t.directive == source::DirectiveKind::Version;
  if (!found) return v;
  v.begin = t.begin;
  // The directive's tokens, comments left out: `version`, the number, the profile.
  std::vector<source::Token> words = lexer.directiveWords();
  const source::Token& name = words.front();
  std::string number = words.size() > 1 && words[1].kind == source::TokenKind::Number
                           ? source::spelledString(text, words[1])
                           : std::string();
  size_t digits = std::find_if(number.begin(), number.end(), [](char c) { return !isDecimalDigit(c); }) - number.begin();
  if (digits == 0 || (digits < number.size() && isIdentifierChar(number[digits]))) {
    // `#version 3x0`, `#version es`, a bare `#version`: quote the directive as written.
    size_t operand = name.end;
    while (operand < text.size() && (text[operand] == ' ' || text[operand] == '\t')) ++operand;
    if (words.size() > 1) operand = words[1].begin;
    v.version = 0;
    v.end = operand;
    v.problem = "'" + quoted(text, v.begin, operand) + "': not a GLSL version";
    v.problemAt = v.begin;
    return v;
  }
  const source::Token& operand = words[1];
  v.end = digits == number.size() ? operand.end : operand.begin + digits;
  // At most 9 digits are read as a number, so the conversion cannot overflow an int.
  long long value = 0;
  for (size_t k = 0; k < digits && k < 10; ++k) value = value * 10 + (number[k] - '0');
  if (digits > 9 || !isGlslVersion(value)) {
    std::string written = number.substr(0, std::min<size_t>(digits, 24));
    if (digits > 24) written += "...";
    v.version = 0;
    v.problem = "#version " + written + " is not a GLSL version";
    v.problemAt = operand.begin;
    return v;
  }
  v.version = static_cast<int>(value);
  bool esVersion = v.version == 300 || v.version == 310 || v.version == 320;
  if (digits == number.size() && words.size() > 2 && words[2].kind == source::TokenKind::Identifier) {
    std::string profile = source::spelledString(text, words[2]);
    if (profile == "es" || profile == "core" || profile == "compatibility") {
      v.es = profile == "es";
      v.compatibility = profile == "compatibility";
      v.end = words[2].end;
      // The profile the language allows at this version (GLSL 4.60 and ESSL 3.20, "Version and
      // profile"): none before 1.50 and in ESSL 1.00, only `es` at 300-320, never `es` elsewhere.
      // The input's error, at the profile, in every stage: a driver refuses the whole shader.
      if (v.version < 150 || v.version == 100)
        v.problem = "#version " + std::to_string(v.version) + " " + profile +
                    ": versions before 150 (and ESSL 1.00) do not allow a profile token";
      else if (esVersion && !v.es)
        v.problem = "#version " + std::to_string(v.version) + " " + profile +
                    ": versions 300, 310 and 320 are ESSL and take only the 'es' profile";
      else if (!esVersion && v.es)
        v.problem = "#version " + std::to_string(v.version) + " es: only versions 300, 310 and 320 have the 'es' profile";
      if (!v.problem.empty()) v.problemAt = words[2].begin;
    } else {
      v.problem = "#version " + std::to_string(v.version) + ": '" + profile.substr(0, 32) +
                  "' is not a profile (es, core or compatibility)";
      v.problemAt = words[2].begin;
    }
  } else if (esVersion) {
    v.es = true;  // what the writer meant; the line is still wrong
    v.problem = "#version " + std::to_string(v.version) + ": versions 300, 310 and 320 are ESSL and need the 'es' profile";
    v.problemAt = operand.begin;
  }
  if (v.version == 100) v.es = true;
  return v;
}

}  // namespace stereoshift
