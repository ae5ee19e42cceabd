// This turns a path into the file's bytes: see file_io.h.
#include "transpiler/source/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace stereoshift {

// POSIX calls, not a stream: a no-op rebuild reads every input and its cache, and copying through
// a stream buffer cost a fifth of it. A file's size is a hint (it may grow or not be regular).
bool readFile(const std::string& path, std::string* contents) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat info {};
  std::string bytes;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) bytes.resize(static_cast<size_t>(info.st_size) + 1);
  if (bytes.size() < 4096) bytes.resize(4096);
  size_t filled = 0;
  bool ok = true;
  for (;;) {
    if (filled == bytes.size()) bytes.resize(bytes.size() * 2);
    const ssize_t got = ::read(fd, bytes.data() + filled, bytes.size() - filled);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      ok = got == 0;
      break;
    }
    filled += static_cast<size_t>(got);
  }
  ::close(fd);
  if (!ok) return false;
  bytes.resize(filled);
  *contents = std::move(bytes);
  return true;
}

}  // namespace stereoshift
