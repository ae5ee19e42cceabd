// Diagnostics in clang/glslc form: `file:line:col: error: message`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace stereoshift {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string file;  // empty: no location
  int line = 0;      // 0: whole file
  int column = 0;    // 0: unknown
  std::string message;

  std::string format() const;  // "file:line:col: error: message"
};

// `text` with its control bytes written as escapes (\n, \r, \t, \xNN), for quoting user text (a TOML
// multi-line string, a file name) inside a diagnostic that must stay on one line.
std::string escapeControlBytes(std::string_view text);

class Diagnostics {
 public:
  void error(std::string file, int line, int column, std::string message);
  void error(std::string file, std::string message) { error(std::move(file), 0, 0, std::move(message)); }
  void warning(std::string file, std::string message);
  void note(std::string file, std::string message);
  void add(Diagnostic d) { list_.push_back(std::move(d)); }
  void append(const Diagnostics& other) { list_.insert(list_.end(), other.list_.begin(), other.list_.end()); }

  int errorCount() const;
  bool hasErrors() const { return errorCount() > 0; }
  const std::vector<Diagnostic>& all() const { return list_; }
  std::string format() const;  // every diagnostic, one per line

 private:
  std::vector<Diagnostic> list_;
};

}  // namespace stereoshift
