// How the CLI commits what it made (see output_commit.h): atomic writes, all-or-nothing sets of
// outputs, reports, and the output-is-an-input check.
#include "cli/output_commit.h"

#include "transpiler/source/file_io.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// Where an output's bytes go: a symbolic link is followed (the link stays a link); a device or pipe
// (/dev/null, /dev/stdout) is written in place: renaming over it would replace it with a regular file.
struct OutputTarget {
  fs::path path;
  bool inPlace = false;
};

OutputTarget targetOf(const fs::path& requested) {
  std::error_code ec;
  OutputTarget target{requested, false};
  if (fs::is_symlink(target.path, ec)) target.path = fs::weakly_canonical(target.path, ec);
  target.inPlace = fs::exists(target.path, ec) && !fs::is_regular_file(target.path, ec);
  return target;
}

// Why nothing can be written at `path`, checked before anything of a set is written: a directory
// there, or a regular file where one of its folders must go. "" when nothing blocks it.
std::string blockedBecause(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return "it is a directory";
  for (fs::path folder = path.parent_path(); !folder.empty(); folder = folder.parent_path()) {
    fs::file_status status = fs::status(folder, ec);
    if (fs::exists(status)) {
      if (!fs::is_directory(status)) return "'" + folder.string() + "' is a file, where a directory must go";
      break;
    }
    if (folder == folder.parent_path()) break;
  }
  return {};
}

Status writeInPlace(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) return plainError("cannot write '" + path.string() + "'");
  return Done{};
}

// The first half of an atomic write: the bytes in a temporary file beside `path`.
// Returns the temporary's path.
Result<fs::path> writeTemporary(const fs::path& path, const std::string& bytes) {
  std::error_code ec;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  fs::path temp = path;
  temp += ".stereoshift-tmp-" + std::to_string(::getpid());
  std::ofstream out(temp, std::ios::binary | std::ios::trunc);
  if (!out) {
    int why = errno;
    return plainError("cannot write '" + path.string() + "': " + std::strerror(why));
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) {
    out.close();
    fs::remove(temp, ec);
    return plainError("cannot write '" + temp.string() + "'");
  }
  return temp;
}

// The second half: the temporary renamed into place (removed when that fails).
Status renameIntoPlace(const fs::path& temp, const fs::path& path) {
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    std::string message = "cannot rename '" + temp.string() + "' to '" + path.string() + "': " + ec.message();
    fs::remove(temp, ec);
    return plainError(std::move(message));
  }
  return Done{};
}

}  // namespace

std::string outputBlockedBecause(const std::string& path) {
  if (path.empty() || path == "-") return {};
  return blockedBecause(targetOf(path).path);
}

// Writes through a temporary file renamed into place: a failure never leaves a partial output.
Status writeAtomically(const fs::path& requested, const std::string& bytes) {
  OutputTarget target = targetOf(requested);
  if (target.inPlace) return writeInPlace(target.path, bytes);
  Result<fs::path> temp = writeTemporary(target.path, bytes);
  if (!temp) return temp.error();
  return renameIntoPlace(*temp, target.path);
}

int writeAllOrNothing(const std::vector<PendingOutput>& outputs, std::ostream& log) {
  struct Staged {
    const PendingOutput* output;
    OutputTarget target;
    fs::path temp;
  };
  std::vector<Staged> staged;
  std::error_code ec;
  // Every path first: one that cannot be written stops the set before any file of it is.
  for (const auto& output : outputs) {
    if (output.path == "-" || output.path.empty()) continue;
    if (std::string why = blockedBecause(targetOf(output.path).path); !why.empty()) {
      log << output.path << ": error: cannot write the output: " << why << "; nothing was written\n";
      return 1;
    }
  }
  for (const auto& output : outputs) {
    if (output.path == "-" || output.path.empty()) continue;
    Staged s{&output, targetOf(output.path), {}};
    if (!s.target.inPlace) {
      Result<fs::path> temp = writeTemporary(s.target.path, output.bytes);
      if (!temp) {
        log << located(temp.error(), output.path).format() << "\n";
        for (const auto& done : staged)
          if (!done.temp.empty()) fs::remove(done.temp, ec);
        return 1;
      }
      s.temp = *temp;
    }
    staged.push_back(std::move(s));
  }
  int errors = 0;
  for (const auto& s : staged) {
    Status written = s.target.inPlace ? writeInPlace(s.target.path, s.output->bytes) : renameIntoPlace(s.temp, s.target.path);
    if (!written) {
      log << located(written.error(), s.output->path).format() << "\n";
      ++errors;
    }
  }
  for (const auto& output : outputs)
    if (output.path == "-" || output.path.empty()) std::cout << output.bytes;
  return errors;
}

bool writeReport(const std::string& path, const nlohmann::json& report) {
  return writeReportText(path, report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

Status writeUnlessHolding(const fs::path& path, const std::string& bytes) {
  std::string existing;
  if (readFile(path.string(), &existing) && existing == bytes) return Done{};
  return writeAtomically(path, bytes);
}

bool writeReportText(const std::string& path, const std::string& text) {
  if (path.empty()) return true;
  if (path == "-") {
    std::cout << text;
    return true;
  }
  // An identical report is left alone (a repeated no-op build rewrites nothing).
  if (Status written = writeUnlessHolding(path, text); !written) {
    std::cerr << "stereoshift: error: " << written.error().message << "\n";
    return false;
  }
  return true;
}

std::optional<std::string> outputThatIsAnInput(const std::vector<std::string>& outputs,
                                               const std::vector<std::string>& inputs) {
  struct stat in {}, out {};
  for (const auto& output : outputs) {
    if (output.empty() || output == "-") continue;
    // stat() follows links: a symbolic link to the input is the input. A device (-o /dev/stdout
    // with the input /dev/stdin on one terminal) is written in place, never replaced: not compared.
    if (::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) continue;
    for (const auto& input : inputs)
      if (::stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino)
        return "output '" + output + "' is the input '" + input + "'; it would be overwritten";
  }
  return std::nullopt;
}

}  // namespace stereoshift
