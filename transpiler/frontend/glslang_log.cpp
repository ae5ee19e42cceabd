#include "transpiler/frontend/glslang_log.h"
#include "passes/source_text.h"

#include <algorithm>
#include <charconv>
#include <regex>
#include <sstream>

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

}  // namespace

void parseGlslangLog(const std::string& log, const std::string& mainFile,
                     const std::vector<std::pair<std::string, std::string>>& sources, Diagnostics& out) {
  // ERROR: <file>:<line>: '<token>' : <message>
  static const std::regex located(R"(^(ERROR|WARNING): (.*?):(\d+): '(.*?)' : (.*)$)");
  static const std::regex plain(R"(^(ERROR|WARNING): (.*)$)");
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, located)) {
      std::string file = m[2];
      // Total: a line number past int (glslang's own type) reads as 0, "whole file", never throws.
      int lineNo = 0;
      const std::string digits = m[3];
      if (std::from_chars(digits.data(), digits.data() + digits.size(), lineNo).ec != std::errc()) lineNo = 0;
      std::string token = m[4];
      std::string message = trim(m[5]);
      if (message == "compilation terminated") continue;  // glslang's follow-up to the real error
      if (file == "0" || file.empty()) file = mainFile;
      int column = 1;
      for (const auto& [name, text] : sources)
        if (name == file) column = columnOf(lineOf(text, lineNo), token);
      std::string full = token.empty() ? message : "'" + token + "' : " + message;
      Diagnostic d{m[1] == "ERROR" ? Severity::Error : Severity::Warning, file, lineNo, column, full};
      out.add(std::move(d));
    } else if (std::regex_match(line, m, plain)) {
      std::string message = trim(m[2]);
      if (message.find("compilation errors.") != std::string::npos) continue;  // summary line
      if (m[1] == "ERROR")
        out.error(mainFile, message);
      else
        out.warning(mainFile, message);
    }
  }
}

}  // namespace stereoshift
