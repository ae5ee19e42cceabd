// See build_noop.h.
#include "cli/build_noop.h"

#include "cli/build_cache.h"
#include "cli/output_commit.h"
#include "transpiler/source/file_io.h"

#include <charconv>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <thread>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

constexpr const char* kNoopFile = ".stereoshift-noop";
constexpr const char* kMarkerFile = ".stereoshift-noop.clock";
constexpr const char* kFormat = "stereoshift-noop 1";

// Length-prefixed blobs: "<bytes>\n<text>\n".
void putBlob(std::string& out, const std::string& text) { out += std::to_string(text.size()) + "\n" + text + "\n"; }

class Reader {
 public:
  explicit Reader(const std::string& text) : text_(text) {}
  bool line(std::string_view* out) {
    const size_t end = text_.find('\n', at_);
    if (end == std::string::npos) return false;
    *out = std::string_view(text_).substr(at_, end - at_);
    at_ = end + 1;
    return true;
  }
  template <typename T>
  bool number(std::string_view word, T* value) {
    auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), *value);
    return ec == std::errc() && end == word.data() + word.size();
  }
  bool blob(std::string* out) {
    std::string_view size;
    size_t bytes = 0;
    if (!line(&size) || !number(size, &bytes) || at_ + bytes + 1 > text_.size() || text_[at_ + bytes] != '\n') return false;
    out->assign(text_, at_, bytes);
    at_ += bytes + 1;
    return true;
  }
  // "<size> <inode> <modified> <changed> <path>"
  bool stamp(std::string* path, FileStamp* s) {
    std::string_view text;
    if (!line(&text)) return false;
    std::string_view words[4];
    for (auto& word : words) {
      const size_t space = text.find(' ');
      if (space == std::string_view::npos) return false;
      word = text.substr(0, space);
      text.remove_prefix(space + 1);
    }
    path->assign(text);
    return number(words[0], &s->size) && number(words[1], &s->inode) && number(words[2], &s->modifiedNs) &&
           number(words[3], &s->changedNs);
  }

 private:
  const std::string& text_;
  size_t at_ = 0;
};

// Every file of the output tree but the record's own files and those a replay rewrites (the report,
// the depfile). Its directories are not stamped: a file added there is none of the build's, and an
// output removed or changed has a stamp of its own.
void outputTree(const fs::path& outDir, const NoopOutcome& outcome, std::vector<std::string>& paths) {
  std::error_code ec;
  const fs::path skipped[] = {outDir / kNoopFile, outDir / kMarkerFile, outcome.reportPath, outcome.depfilePath};
  for (fs::recursive_directory_iterator it(outDir, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    const fs::path& path = it->path();
    std::error_code kind;
    bool skip = it->is_directory(kind);
    for (const auto& s : skipped) skip |= !s.empty() && path == s;
    if (!skip) paths.push_back(path.string());
  }
}

// The stamps of `paths` taken against the file system's clock: nullopt when one of them changed
// within the current tick or later (recording it could miss a change in the same tick).
std::optional<std::string> stampsAgainstTheClock(const fs::path& outDir, const std::vector<std::string>& paths) {
  if (Status marked = writeAtomically(outDir / kMarkerFile, "clock\n"); !marked) return std::nullopt;
  const FileStamp clock = statStamp(outDir / kMarkerFile);
  if (clock.size < 0) return std::nullopt;
  std::string out = std::to_string(paths.size()) + "\n";
  for (const auto& path : paths) {
    if (path.find('\n') != std::string::npos) return std::nullopt;
    const FileStamp s = statStamp(path);
    if (s.size >= 0 && s.changedNs >= clock.changedNs) return std::nullopt;
    out += std::to_string(s.size) + " " + std::to_string(s.inode) + " " + std::to_string(s.modifiedNs) + " " +
           std::to_string(s.changedNs) + " " + path + "\n";
  }
  return out;
}

}  // namespace

std::string noopRunKey(const std::vector<std::string>& commandLine) {
  std::error_code ec;
  std::string key = toolIdentity() + "\n" + fs::current_path(ec).string() + "\n";
  for (const auto& word : commandLine) key += std::to_string(word.size()) + ":" + word + "\n";
  return key;
}

void recordNoop(const fs::path& source, const fs::path& outDir, const std::string& runKey, const NoopOutcome& outcome,
                const std::vector<std::string>& dependencies) {
  std::vector<std::string> paths = {source.string()};
  paths.insert(paths.end(), dependencies.begin(), dependencies.end());
  outputTree(outDir, outcome, paths);
  std::optional<std::string> stamps;
  // A file written in the last tick (this run's outputs) is recorded once the clock has moved on.
  for (int attempt = 0; attempt < 4 && !stamps; ++attempt) {
    if (attempt) std::this_thread::sleep_for(std::chrono::milliseconds(2 << attempt));
    stamps = stampsAgainstTheClock(outDir, paths);
  }
  std::error_code ec;
  fs::remove(outDir / kMarkerFile, ec);
  if (!stamps) return;
  std::string record = std::string(kFormat) + "\n";
  putBlob(record, runKey);
  putBlob(record, outcome.reportPath.string());
  putBlob(record, outcome.reportText);
  putBlob(record, outcome.depfilePath.string());
  putBlob(record, outcome.depfileText);
  putBlob(record, outcome.messages);
  record += *stamps;
  (void)writeAtomically(outDir / kNoopFile, record);
}

bool replayNoop(const fs::path& outDir, const std::string& runKey) {
  std::string text;
  if (!readFile((outDir / kNoopFile).string(), &text)) return false;
  Reader in(text);
  std::string_view format;
  std::string key, reportPath, reportText, depfilePath, depfileText, messages;
  if (!in.line(&format) || format != kFormat || !in.blob(&key) || key != runKey || !in.blob(&reportPath) ||
      !in.blob(&reportText) || !in.blob(&depfilePath) || !in.blob(&depfileText) || !in.blob(&messages))
    return false;
  std::string_view countText;
  size_t count = 0;
  if (!in.line(&countText) || !in.number(countText, &count)) return false;
  std::string path;
  FileStamp recorded;
  for (size_t i = 0; i < count; ++i)
    if (!in.stamp(&path, &recorded) || !(statStamp(path) == recorded)) return false;
  if (!writeReportText(reportPath, reportText)) return false;
  if (!depfilePath.empty())
    if (Status written = writeUnlessHolding(depfilePath, depfileText); !written) {
      std::cerr << located(written.error(), depfilePath).format() << "\n";
      return false;
    }
  std::cerr << messages;
  return true;
}

void forgetNoop(const fs::path& outDir) {
  std::error_code ec;
  fs::remove(outDir / kNoopFile, ec);
}

}  // namespace stereoshift
