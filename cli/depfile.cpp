// Make/Ninja depfiles (see depfile.h): written with spaces and '#' escaped by a backslash and '$'
// doubled (Ninja's and GNU make's shared rules), read back by the inverse rules.
#include "cli/depfile.h"

#include "cli/source_reading.h"

#include <algorithm>

namespace stereoshift {

// Make/Ninja depfile text: `target...: dependency...`, spaces and '#' escaped with a backslash, '$'
// doubled (Ninja's and GNU make's shared rules).
std::string makeDepfile(const std::vector<std::string>& targets, std::vector<std::string> dependencies) {
  auto escape = [](const std::string& path) {
    std::string out;
    for (char c : path) {
      if (c == ' ' || c == '#') out += '\\';
      if (c == '$') out += '$';
      out += c;
    }
    return out;
  };
  std::sort(dependencies.begin(), dependencies.end());
  dependencies.erase(std::unique(dependencies.begin(), dependencies.end()), dependencies.end());
  std::string text;
  for (size_t i = 0; i < targets.size(); ++i) text += (i ? " " : "") + escape(targets[i]);
  text += ":";
  for (const auto& d : dependencies) text += " \\\n  " + escape(d);
  return text + "\n";
}

std::optional<std::string> conversionDepfile(const nlohmann::json& reports, const std::vector<SourceFile>& sources) {
  std::vector<std::string> targets, dependencies;
  for (const auto& r : reports)
    if (r.contains("output_file")) targets.push_back(r["output_file"].get<std::string>());
  for (const auto& s : sources)
    if (s.path != kStdinName) dependencies.push_back(s.path);
  for (const auto& r : reports)
    for (const auto& inc : r.value("included_files", nlohmann::json::array())) dependencies.push_back(inc.get<std::string>());
  if (targets.empty()) return std::nullopt;
  return makeDepfile(targets, dependencies);
}

std::optional<Depfile> parseDepfile(const std::string& text) {
  // The inverse of makeDepfile: `\ ` and `\#` are literal, `$$` is `$`, a backslash before a
  // newline continues the line; the first word ending in ':' closes the targets.
  Depfile parsed;
  bool inTargets = true, sawColon = false;
  std::string word;
  auto endWord = [&] {
    if (word.empty()) return;
    if (inTargets && word.back() == ':') {
      word.pop_back();
      if (!word.empty()) parsed.targets.push_back(word);
      inTargets = false;
      sawColon = true;
    } else {
      (inTargets ? parsed.targets : parsed.dependencies).push_back(word);
    }
    word.clear();
  };
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\\' && i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '#')) {
      word += text[++i];
    } else if (c == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
      endWord();
      ++i;
    } else if (c == '$' && i + 1 < text.size() && text[i + 1] == '$') {
      word += '$';
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      endWord();
    } else {
      word += c;
    }
  }
  endWord();
  if (!sawColon) return std::nullopt;
  return parsed;
}

}  // namespace stereoshift
