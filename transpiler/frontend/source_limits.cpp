// This turns shader source text into the first place its brackets nest past the front end's limit
// (see source_limits.h), with its line and column, in one linear pass over the text.
#include "transpiler/frontend/source_limits.h"
#include <algorithm>
#include <cstdio>

namespace stereoshift {

std::optional<LimitViolation> findNestingViolation(const std::string& text) {
  int line = 1;
  size_t lineStart = 0;
  int depth = 0;
  auto positionOf = [&](size_t at) {
    LimitViolation v;
    v.line = line;
    v.column = static_cast<int>(at - lineStart) + 1;
    return v;
  };
  // Keeps line and lineStart right when [from, to) is skipped in one step.
  auto skipTo = [&](size_t from, size_t to) {
    for (size_t k = from; k < to; ++k)
      if (text[k] == '\n') {
        ++line;
        lineStart = k + 1;
      }
    return to;
  };
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\n') {
      ++line;
      lineStart = ++i;
    } else if (c == '/' && next == '/') {
      size_t end = text.find('\n', i);
      i = end == std::string::npos ? text.size() : end;
    } else if (c == '/' && next == '*') {
      size_t end = text.find("*/", i + 2);
      i = skipTo(i, end == std::string::npos ? text.size() : end + 2);
    } else if (c == '"') {
      // String literals (#include names, printf formats) end at the closing quote or the line.
      size_t k = i + 1;
      while (k < text.size() && text[k] != '"' && text[k] != '\n') k += text[k] == '\\' ? 2 : 1;
      i = skipTo(i, std::min(text.size(), k < text.size() && text[k] == '"' ? k + 1 : k));
    } else if (c == '(' || c == '[' || c == '{') {
      if (++depth > kMaxBracketNesting) {
        LimitViolation v = positionOf(i);
        v.message = "brackets nest deeper than " + std::to_string(kMaxBracketNesting) +
                    " levels here (the front end's limit: glslang parses nested brackets by recursion)";
        return v;
      }
      ++i;
    } else if (c == ')' || c == ']' || c == '}') {
      if (depth > 0) --depth;
      ++i;
    } else {
      ++i;
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
