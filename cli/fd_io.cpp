#include "cli/fd_io.h"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

namespace stereoshift {

namespace {

template <class Write>
bool writeLoop(const void* data, size_t size, Write write) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    ssize_t n = write(p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

bool writeAll(int fd, const void* data, size_t size) {
  return writeLoop(data, size, [fd](const char* p, size_t n) { return ::write(fd, p, n); });
}

bool sendAll(int fd, const void* data, size_t size) {
  return writeLoop(data, size, [fd](const char* p, size_t n) { return ::send(fd, p, n, MSG_NOSIGNAL); });
}

bool readAll(int fd, void* data, size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    ssize_t n = ::read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace stereoshift
