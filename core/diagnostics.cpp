#include "core/diagnostics.h"

#include <algorithm>
#include <sstream>

namespace stereoshift {

std::string Diagnostic::format() const {
  std::string out;
  if (!file.empty()) {
    out += file;
    if (line > 0) {
      out += ":" + std::to_string(line);
      if (column > 0) out += ":" + std::to_string(column);
    }
    out += ": ";
  }
  switch (severity) {
    case Severity::Error: out += "error: "; break;
    case Severity::Warning: out += "warning: "; break;
    case Severity::Note: out += "note: "; break;
  }
  return out + message;
}

void Diagnostics::error(std::string file, int line, int column, std::string message) {
  list_.push_back({Severity::Error, std::move(file), line, column, std::move(message)});
}
void Diagnostics::warning(std::string file, std::string message) {
  list_.push_back({Severity::Warning, std::move(file), 0, 0, std::move(message)});
}
void Diagnostics::note(std::string file, std::string message) {
  list_.push_back({Severity::Note, std::move(file), 0, 0, std::move(message)});
}

std::string escapeControlBytes(std::string_view text) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (unsigned char c : text) {
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else out += static_cast<char>(c);
  }
  return out;
}

int Diagnostics::errorCount() const {
  return static_cast<int>(std::count_if(list_.begin(), list_.end(),
                                        [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

std::string Diagnostics::format() const {
  std::string out;
  for (const auto& d : list_) out += d.format() + "\n";
  return out;
}

}  // namespace stereoshift
