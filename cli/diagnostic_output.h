// How every command ends its messages: the diagnostics printed as they are formatted, the
// clang-style summary "N errors generated." on standard error, and how they look on the way out:
// each located diagnostic followed by its source line with a caret under the column, coloured on a
// terminal (as clang prints them).
#pragma once

#include "transpiler/stereoshift.h"  // Diagnostics

#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace stereoshift {

// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log);
// "N errors generated." on standard error when N > 0.
void printErrorSummary(int errors);

// How the messages on standard error look. The text the tool composes (logs, the build cache, the
// report's `errors`) stays plain; the style is applied once, where the text leaves the process.
struct DiagnosticStyle {
  bool caret = true;    // the source line and a caret under the column after `file:line:col:` messages
  bool colour = false;  // severity and location in colour (ANSI escapes)
};

// --color auto|always|never (clang's -fdiagnostics-color): colour for `always`, and for `auto` when
// standard error is a terminal that is not `dumb` and NO_COLOR is not set.
bool colourWanted(const std::string& when);

// `text` (whole lines) as it is shown in `style`: a line `file:line:col: error|warning|note: message`
// gets the colours and, when the file (or the standard input's text, see rememberSourceText) has that
// line and the column lies on it, the line and a caret. Other lines pass as they are.
std::string renderDiagnostics(std::string_view text, const DiagnosticStyle& style);

// The standard input's text, which cannot be read again when a diagnostic names <stdin>.
void rememberSourceText(const std::string& name, std::string text);

// While alive, std::cerr goes through renderDiagnostics: whole lines are rendered as they complete;
// a flush passes on a partial line only when it is terminal control (the build's progress bar,
// "\r...\x1b[K"), so a message written in pieces is rendered whole. Restores std::cerr when it ends.
// One per process: a stream made while another is alive sets that one's style until it ends.
class DiagnosticStream {
 public:
  explicit DiagnosticStream(const DiagnosticStyle& style);
  ~DiagnosticStream();
  DiagnosticStream(const DiagnosticStream&) = delete;
  DiagnosticStream& operator=(const DiagnosticStream&) = delete;

  class Buffer;

 private:
  Buffer* buffer_;             // null when another stream was already in force
  std::streambuf* previous_;   // what std::cerr wrote to before
  DiagnosticStyle outerStyle_;  // that other stream's style, given back at the end
};

}  // namespace stereoshift
