#include "transpiler/frontend/glslang_log.h"
#include "transpiler/source/identifiers.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <sstream>
#include <string_view>

namespace stereoshift {

namespace {

std::string lineOf(const std::string& text, int line) {
  std::istringstream in(text);
  std::string current;
  for (int i = 1; std::getline(in, current); ++i)
    if (i == line) return current;
  return {};
}

// 1-based column of `token` on `lineText` (as a whole word when it is an identifier), or 1.
int columnOf(const std::string& lineText, const std::string& token) {
  if (token.empty()) {
    size_t first = lineText.find_first_not_of(" \t");
    return first == std::string::npos ? 1 : static_cast<int>(first) + 1;
  }
  bool ident = std::all_of(token.begin(), token.end(), isIdentifierChar);
  for (size_t at = lineText.find(token); at != std::string::npos; at = lineText.find(token, at + 1)) {
    if (!ident) return static_cast<int>(at) + 1;
    bool startOk = at == 0 || !isIdentifierChar(lineText[at - 1]);
    size_t end = at + token.size();
    bool endOk = end >= lineText.size() || !isIdentifierChar(lineText[end]);
    if (startOk && endOk) return static_cast<int>(at) + 1;
  }
  size_t first = lineText.find_first_not_of(" \t");
  return first == std::string::npos ? 1 : static_cast<int>(first) + 1;
}

std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  size_t first = s.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first);
}

// One line of glslang's log, taken apart by hand: the format needs no backtracking, and std::regex
// costs seconds of compile time per use (more under the sanitizers) and is slow to run. glslang
// writes three forms:
//   ERROR: <file>:<line>: '<token>' : <message>     (located)
//   ERROR: <message>                                (plain; also WARNING)
//   <file>(<line>): error at column <n>, <message>  (HLSL's parser, where it gives up: a stray `}`)
// The file is the shortest prefix followed by ":<digits>: '", the token runs to the first "' : " after
// its opening quote, as glslang never puts that sequence in a file name. A line with a carriage return
// is not glslang's (it writes \n only) and is skipped.
struct LogLine {
  bool error = false;
  bool located = false;
  std::string file, digits, token, message;
  std::string columnDigits;  // the HLSL parser's form gives the column itself
};

bool allDigits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// `<file>(<line>): error at column <n>, <message>`: the last "(" before "): error at column " opens
// the line number (a file name may hold parentheses, the number cannot).
std::optional<LogLine> splitHlslParserLine(std::string_view rest) {
  constexpr std::string_view kMarker = "): error at column ";
  size_t marker = rest.find(kMarker);
  if (marker == std::string_view::npos) return std::nullopt;
  size_t open = rest.rfind('(', marker);
  if (open == std::string_view::npos || !allDigits(rest.substr(open + 1, marker - open - 1))) return std::nullopt;
  size_t columnStart = marker + kMarker.size();
  size_t comma = rest.find(", ", columnStart);
  if (comma == std::string_view::npos || !allDigits(rest.substr(columnStart, comma - columnStart))) return std::nullopt;
  LogLine out;
  out.error = out.located = true;
  out.file = std::string(rest.substr(0, open));
  out.digits = std::string(rest.substr(open + 1, marker - open - 1));
  out.columnDigits = std::string(rest.substr(columnStart, comma - columnStart));
  out.message = std::string(rest.substr(comma + 2));
  return out;
}

std::optional<LogLine> splitLogLine(const std::string& line) {
  LogLine out;
  std::string_view rest(line);
  if (rest.find('\r') != std::string_view::npos) return std::nullopt;
  if (rest.starts_with("ERROR: ")) {
    out.error = true;
    rest.remove_prefix(7);
  } else if (rest.starts_with("WARNING: ")) {
    rest.remove_prefix(9);
  } else {
    return splitHlslParserLine(rest);
  }
  for (size_t colon = rest.find(':'); colon != std::string_view::npos; colon = rest.find(':', colon + 1)) {
    size_t digitsEnd = colon + 1;
    while (digitsEnd < rest.size() && rest[digitsEnd] >= '0' && rest[digitsEnd] <= '9') ++digitsEnd;
    if (digitsEnd == colon + 1 || rest.substr(digitsEnd, 3) != ": '") continue;
    size_t tokenStart = digitsEnd + 3;
    size_t tokenEnd = rest.find("' : ", tokenStart);
    if (tokenEnd == std::string_view::npos) break;  // no later candidate can have one either
    out.located = true;
    out.file = std::string(rest.substr(0, colon));
    out.digits = std::string(rest.substr(colon + 1, digitsEnd - colon - 1));
    out.token = std::string(rest.substr(tokenStart, tokenEnd - tokenStart));
    out.message = std::string(rest.substr(tokenEnd + 4));
    return out;
  }
  out.message = std::string(rest);
  return out;
}

}  // namespace

void parseGlslangLog(const std::string& log, const std::string& mainFile,
                     const std::vector<std::pair<std::string, std::string>>& sources, Diagnostics& out) {
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    std::optional<LogLine> parsed = splitLogLine(line);
    if (!parsed) continue;
    if (parsed->located) {
      std::string file = parsed->file;
      // Total: a line number past int (glslang's own type) reads as 0, "whole file", never throws.
      int lineNo = 0;
      const std::string& digits = parsed->digits;
      if (std::from_chars(digits.data(), digits.data() + digits.size(), lineNo).ec != std::errc()) lineNo = 0;
      const std::string& token = parsed->token;
      std::string message = trim(parsed->message);
      if (message == "compilation terminated") continue;  // glslang's follow-up to the real error
      if (file == "0" || file.empty()) file = mainFile;
      int column = 1;
      if (!parsed->columnDigits.empty()) {
        if (std::from_chars(parsed->columnDigits.data(), parsed->columnDigits.data() + parsed->columnDigits.size(), column)
                .ec != std::errc() || column < 1)
          column = 1;
      } else {
        for (const auto& [name, text] : sources)
          if (name == file) column = columnOf(lineOf(text, lineNo), token);
      }
      std::string full = token.empty() ? message : "'" + token + "' : " + message;
      // The HLSL parser names no token: name what is written where it stopped.
      if (!parsed->columnDigits.empty())
        for (const auto& [name, text] : sources)
          if (name == file) {
            std::string lineText = lineOf(text, lineNo);
            size_t at = static_cast<size_t>(column - 1), end = at;
            while (end < lineText.size() && isIdentifierChar(lineText[end])) ++end;
            if (end == at && at < lineText.size() && !std::isspace(static_cast<unsigned char>(lineText[at]))) end = at + 1;
            if (end > at && message.ends_with("."))
              full = message.substr(0, message.size() - 1) + " at '" + lineText.substr(at, std::min<size_t>(end - at, 32)) + "'";
          }
      Diagnostic d{parsed->error ? Severity::Error : Severity::Warning, file, lineNo, column, full};
      out.add(std::move(d));
    } else {
      std::string message = trim(parsed->message);
      if (message.find("compilation errors.") != std::string::npos) continue;  // summary line
      if (parsed->error)
        out.error(mainFile, message);
      else
        out.warning(mainFile, message);
    }
  }
}

}  // namespace stereoshift
