// How the CLI reads its input shaders (see source_reading.h).
#include "cli/source_reading.h"

#include "cli/diagnostic_output.h"
#include "cli/test_hook.h"
#include "transpiler/source/file_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {

// Why `path` cannot be read, in the words the system uses.
std::string unreadableBecause(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return "no such file";
  if (fs::is_directory(status)) return "it is a directory";
  errno = 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::strerror(errno);
  ::close(fd);
  return "reading it failed";
}

int readSources(const std::vector<std::string>& paths, std::vector<SourceFile>* sources, std::ostream& log) {
  int failed = 0;
  for (const auto& p : paths) {
    hangIfTestAsks(p);
    SourceFile s{p, {}};
    std::error_code ec;
    if (p == "-") {
      // Standard input, as glslc reads it: the stage and language then come from -S / -x or the
      // text, and diagnostics name it <stdin>.
      s.path = kStdinName;
      std::ostringstream text;
      text << std::cin.rdbuf();
      s.contents = text.str();
      rememberSourceText(kStdinName, s.contents);  // for the source line under its diagnostics
    } else if (fs::is_directory(p, ec) || !readFile(p, &s.contents)) {
      log << p << ": error: cannot read file: " << unreadableBecause(p) << "\n";
      ++failed;
      continue;
    }
    sources->push_back(std::move(s));
  }
  return failed;
}

}  // namespace stereoshift
