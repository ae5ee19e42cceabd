// This turns shader source text into the first place its brackets nest past the front end's limit
// (see source_limits.h), with its line and column, in one pass of the lexer over the text.
#include "transpiler/frontend/source_limits.h"

#include "transpiler/source/lexer.h"

#include <cstdio>

namespace stereoshift {

std::optional<LimitViolation> findNestingViolation(const std::string& text) {
  source::Lexer lexer(text);
  source::Token t;
  int depth = 0;
  while (lexer.next(t)) {
    if (t.kind != source::TokenKind::Punctuation) continue;  // directives' brackets are read as their tokens
    char c = text[t.begin];
    if (c == '(' || c == '[' || c == '{') {
      if (++depth > kMaxBracketNesting) {
        LimitViolation v;
        v.line = static_cast<int>(t.line);
        v.column = static_cast<int>(t.column);
        v.message = "brackets nest deeper than " + std::to_string(kMaxBracketNesting) +
                    " levels here (the front end's limit: glslang parses nested brackets by recursion)";
        return v;
      }
    } else if ((c == ')' || c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

std::string describeBytes(size_t bytes) {
  char buffer[32];
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0)
    std::snprintf(buffer, sizeof buffer, "%zu MiB", bytes >> 20);
  else if (bytes >= (1u << 20))
    std::snprintf(buffer, sizeof buffer, "%.1f MiB", static_cast<double>(bytes) / (1u << 20));
  else
    std::snprintf(buffer, sizeof buffer, "%zu KiB", (bytes + 1023) / 1024);
  return buffer;
}

}  // namespace stereoshift
