// How every command ends its messages (see diagnostic_output.h).
#include "cli/diagnostic_output.h"

#include <unistd.h>

#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

namespace stereoshift {

// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log) {
  log << diags.format();
  return diags.errorCount();
}

void printErrorSummary(int errors) {
  if (errors > 0) std::cerr << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
}

bool colourWanted(const std::string& when) {
  if (when == "always") return true;
  if (when != "auto") return false;
  const char* term = std::getenv("TERM");
  const char* noColour = std::getenv("NO_COLOR");
  return ::isatty(STDERR_FILENO) && term && std::string(term) != "dumb" && !(noColour && *noColour);
}

namespace {

// A source line longer than this (a minified shader) is not shown: it would bury the message.
constexpr size_t kLongestShownLine = 1000;
// Files past this size are not read for their lines.
constexpr std::streamoff kLargestReadSource = 16 << 20;

// The lines of the files diagnostics name, read once each; the standard input's as it was given.
std::map<std::string, std::vector<std::string>>& sourceLines() {
  static std::map<std::string, std::vector<std::string>> lines;
  return lines;
}

std::vector<std::string> splitLines(std::string_view text) {
  std::vector<std::string> lines;
  while (!text.empty()) {
    size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.emplace_back(line);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

const std::vector<std::string>& linesOf(const std::string& file) {
  auto& cache = sourceLines();
  if (auto it = cache.find(file); it != cache.end()) return it->second;
  std::vector<std::string> lines;
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (in && in.tellg() <= kLargestReadSource) {
    std::string text(static_cast<size_t>(in.tellg()), '\0');
    in.seekg(0);
    if (in.read(text.data(), static_cast<std::streamsize>(text.size())) && text.find('\0') == std::string::npos)
      lines = splitLines(text);
  }
  return cache.emplace(file, std::move(lines)).first->second;
}

// A message line taken apart: `location` is everything before ": severity: ", which ends in
// `:line:col` or `:line` when the message is located in a file.
struct MessageLine {
  std::string_view location, severity, message;
  std::string file;
  int line = 0, column = 0;
};

// The trailing ":N" of `text`, taken off it; 0 when there is none.
int takeNumberSuffix(std::string_view* text) {
  size_t colon = text->rfind(':');
  if (colon == std::string_view::npos || colon + 1 == text->size()) return 0;
  int value = 0;
  auto [end, ec] = std::from_chars(text->data() + colon + 1, text->data() + text->size(), value);
  if (ec != std::errc() || end != text->data() + text->size() || value <= 0) return 0;
  text->remove_suffix(text->size() - colon);
  return value;
}

bool parseMessageLine(std::string_view line, MessageLine* m) {
  size_t best = std::string_view::npos;
  std::string_view severity;
  for (std::string_view s : {": error: ", ": warning: ", ": note: "}) {
    size_t at = line.find(s);
    if (at != std::string_view::npos && at < best) best = at, severity = s;
  }
  if (best == std::string_view::npos || best == 0) return false;
  m->location = line.substr(0, best);
  m->severity = severity.substr(2, severity.size() - 4);
  m->message = line.substr(best + severity.size());
  std::string_view file = m->location;
  int last = takeNumberSuffix(&file);
  int before = last ? takeNumberSuffix(&file) : 0;
  m->line = before ? before : last;
  m->column = before ? last : 0;
  m->file = std::string(file);
  return true;
}

const char* severityColour(std::string_view severity) {
  if (severity == "error") return "\x1b[1;31m";
  if (severity == "warning") return "\x1b[1;35m";
  return "\x1b[1;36m";
}

void renderLine(std::string_view line, const DiagnosticStyle& style, std::string* out) {
  MessageLine m;
  if (!parseMessageLine(line, &m)) {
    out->append(line);
    out->push_back('\n');
    return;
  }
  if (style.colour) {
    *out += "\x1b[1m" + std::string(m.location) + ": " + severityColour(m.severity) + std::string(m.severity) +
            ": \x1b[0m\x1b[1m" + std::string(m.message) + "\x1b[0m\n";
  } else {
    out->append(line);
    out->push_back('\n');
  }
  if (!style.caret || m.line <= 0 || m.column <= 0) return;
  const std::vector<std::string>& lines = linesOf(m.file);
  if (static_cast<size_t>(m.line) > lines.size()) return;
  const std::string& source = lines[static_cast<size_t>(m.line) - 1];
  if (source.size() > kLongestShownLine || static_cast<size_t>(m.column) > source.size() + 1) return;
  // The caret under the column: the line's own tabs kept, so it lines up however tabs are shown.
  std::string indent;
  for (size_t i = 0; i + 1 < static_cast<size_t>(m.column); ++i) indent.push_back(source[i] == '\t' ? '\t' : ' ');
  *out += source + "\n" + indent + (style.colour ? "\x1b[1;32m^\x1b[0m" : "^") + "\n";
}

}  // namespace

std::string renderDiagnostics(std::string_view text, const DiagnosticStyle& style) {
  std::string out;
  while (!text.empty()) {
    size_t end = text.find('\n');
    if (end == std::string_view::npos) {
      out.append(text);  // a partial line: as it is
      break;
    }
    renderLine(text.substr(0, end), style, &out);
    text.remove_prefix(end + 1);
  }
  return out;
}

void rememberSourceText(const std::string& name, std::string text) { sourceLines()[name] = splitLines(text); }

class DiagnosticStream::Buffer : public std::streambuf {
 public:
  Buffer(std::streambuf* out, const DiagnosticStyle& style) : out_(out), style_(style) {}
  ~Buffer() override { passOn(pending_.size()); }
  // Renders what is pending in the style it was written in, then takes `style`; returns the old one.
  DiagnosticStyle setStyle(const DiagnosticStyle& style) {
    passOn(pending_.size());
    DiagnosticStyle old = style_;
    style_ = style;
    return old;
  }

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    pending_.push_back(static_cast<char>(c));
    if (c == '\n') passOn(pending_.size());
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    pending_.append(s, static_cast<size_t>(n));
    if (size_t last = pending_.rfind('\n'); last != std::string::npos) passOn(last + 1);
    return n;
  }
  int sync() override {
    // std::cerr flushes after every <<: a message written in pieces waits for its newline, but
    // terminal control (a progress bar redrawn with \r and ESC[K) goes out now.
    if (pending_.find_first_of("\r\x1b") != std::string::npos) passOn(pending_.size());
    return out_->pubsync();
  }

 private:
  // Renders and writes the first `size` bytes of what is pending.
  void passOn(size_t size) {
    if (size == 0) return;
    std::string shown = renderDiagnostics(std::string_view(pending_).substr(0, size), style_);
    pending_.erase(0, size);
    out_->sputn(shown.data(), static_cast<std::streamsize>(shown.size()));
  }

  std::streambuf* out_;
  DiagnosticStyle style_;
  std::string pending_;
};

namespace {
// The stream in force in this process. A command run inside another (a conversion-service worker
// forked from the command that started the server) renders through the one already there, in its
// own style: two would place each caret twice.
DiagnosticStream::Buffer* activeBuffer = nullptr;
}  // namespace

DiagnosticStream::DiagnosticStream(const DiagnosticStyle& style) {
  if (activeBuffer) {
    std::cerr.flush();
    outerStyle_ = activeBuffer->setStyle(style);
    buffer_ = nullptr;
    previous_ = nullptr;
    return;
  }
  buffer_ = activeBuffer = new Buffer(std::cerr.rdbuf(), style);
  previous_ = std::cerr.rdbuf(buffer_);
}

DiagnosticStream::~DiagnosticStream() {
  std::cerr.flush();
  if (!buffer_) {
    activeBuffer->setStyle(outerStyle_);
    return;
  }
  std::cerr.rdbuf(previous_);
  activeBuffer = nullptr;
  delete buffer_;  // passes on what is left
  std::cerr.flush();
}

}  // namespace stereoshift
