// The conversion service's message framing, tool identity and socket directory (see the header;
// the messages' bodies are result_codec's).
#include "cli/service_protocol.h"

#include "cli/fd_io.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

extern char** environ;

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// Far beyond any shader and its outputs; a larger length is a broken or foreign peer.
constexpr uint64_t kLargestMessage = uint64_t(1) << 32;
// The variables that switch the service itself: a worker must not look at them.
const char* const kServiceSwitches[] = {"STEREOSHIFT_SERVICE", "STEREOSHIFT_SERVICE_IDLE", "STEREOSHIFT_SERVICE_DIR",
                                        "STEREOSHIFT_SERVICE_LOG"};

bool isServiceSwitch(const std::string& name) {
  for (const char* s : kServiceSwitches)
    if (name == s) return true;
  return false;
}

// Reads exactly `size` bytes before `deadline` (none when timeoutSeconds <= 0).
bool readExactly(int fd, char* data, size_t size, double timeoutSeconds, std::chrono::steady_clock::time_point deadline) {
  while (size > 0) {
    if (timeoutSeconds > 0) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
      if (left <= 0) return false;
      pollfd p{fd, POLLIN, 0};
      int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0) return false;
    }
    ssize_t n = ::read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

uint64_t fnv1a(const std::string& bytes) {
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace

bool sendMessage(int fd, const std::string& bytes) {
  uint64_t size = bytes.size();
  char header[8];
  for (int i = 0; i < 8; ++i) header[i] = static_cast<char>((size >> (8 * i)) & 0xff);
  std::string message(header, sizeof header);
  message += bytes;
  return sendAll(fd, message.data(), message.size());
}

bool receiveMessage(int fd, std::string* bytes, double timeoutSeconds) {
  auto deadline = std::chrono::steady_clock::now() +
                  std::chrono::milliseconds(static_cast<long long>(timeoutSeconds > 0 ? timeoutSeconds * 1000 : 0));
  unsigned char header[8];
  if (!readExactly(fd, reinterpret_cast<char*>(header), sizeof header, timeoutSeconds, deadline)) return false;
  uint64_t size = 0;
  for (int i = 0; i < 8; ++i) size |= uint64_t(header[i]) << (8 * i);
  if (size > kLargestMessage) return false;
  bytes->assign(size, '\0');
  return readExactly(fd, bytes->data(), size, timeoutSeconds, deadline);
}

std::vector<std::pair<std::string, std::optional<std::string>>> serviceEnvironment() {
  std::vector<std::pair<std::string, std::optional<std::string>>> environment;
  for (char** e = environ; e && *e; ++e) {
    std::string entry = *e;
    size_t equals = entry.find('=');
    if (equals == std::string::npos) continue;
    std::string name = entry.substr(0, equals);
    if (name.rfind("STEREOSHIFT_", 0) != 0 || isServiceSwitch(name)) continue;
    environment.emplace_back(name, entry.substr(equals + 1));
  }
  return environment;
}

void applyServiceEnvironment(const std::vector<std::pair<std::string, std::optional<std::string>>>& environment) {
  // First every STEREOSHIFT_* variable the server itself has (it inherited the first client's), then the request's.
  std::vector<std::string> present;
  for (char** e = environ; e && *e; ++e) {
    std::string entry = *e;
    size_t equals = entry.find('=');
    if (equals != std::string::npos && entry.rfind("STEREOSHIFT_", 0) == 0) present.push_back(entry.substr(0, equals));
  }
  for (const auto& name : present) ::unsetenv(name.c_str());
  for (const auto& [name, value] : environment)
    if (value && name.rfind("STEREOSHIFT_", 0) == 0) ::setenv(name.c_str(), value->c_str(), 1);
}

std::optional<std::string> serverIdentity() {
  std::error_code ec;
  fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  struct stat s {};
  if (::stat(executable.c_str(), &s) != 0) return std::nullopt;
  std::string description = executable.string();
  for (long long field : {static_cast<long long>(s.st_dev), static_cast<long long>(s.st_ino),
                          static_cast<long long>(s.st_size), static_cast<long long>(s.st_mtim.tv_sec),
                          static_cast<long long>(s.st_mtim.tv_nsec), static_cast<long long>(s.st_ctim.tv_sec),
                          static_cast<long long>(s.st_ctim.tv_nsec)}) {
    description += '\0';
    description += std::to_string(field);
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(description)));
  return std::string(hex);
}

std::optional<ServicePaths> servicePaths(const std::string& identity, std::string* why, bool* unsafe) {
  *unsafe = false;
  std::string directory;
  if (const char* own = std::getenv("STEREOSHIFT_SERVICE_DIR"); own && *own) {
    directory = own;
  } else if (const char* runtime = std::getenv("XDG_RUNTIME_DIR"); runtime && *runtime) {
    directory = std::string(runtime) + "/stereoshift";
  } else {
    directory = "/tmp/stereoshift-" + std::to_string(::geteuid());
  }
  // mkdir is atomic: either this user creates it 0700 now, or it exists and is checked below (a
  // directory someone else made in /tmp first is theirs, and refused).
  if (::mkdir(directory.c_str(), 0700) != 0 && errno != EEXIST) {
    *why = "cannot create the service directory '" + directory + "': " + std::strerror(errno);
    return std::nullopt;
  }
  struct stat s {};
  if (::lstat(directory.c_str(), &s) != 0) {
    *why = "cannot examine the service directory '" + directory + "': " + std::strerror(errno);
    return std::nullopt;
  }
  *unsafe = true;
  if (!S_ISDIR(s.st_mode)) {
    *why = "the service directory '" + directory + "' is not a directory (a symbolic link or a file)";
    return std::nullopt;
  }
  if (s.st_uid != ::geteuid()) {
    *why = "the service directory '" + directory + "' belongs to another user (uid " + std::to_string(s.st_uid) + ")";
    return std::nullopt;
  }
  if ((s.st_mode & 077) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(s.st_mode & 07777));
    *why = "the service directory '" + directory + "' has mode " + mode + "; it must be private to its owner (0700)";
    return std::nullopt;
  }
  *unsafe = false;
  // A Unix socket's path is limited (108 bytes on Linux, including the terminating zero).
  std::string socket = directory + "/" + identity + ".sock";
  if (socket.size() >= 108) {
    *why = "the service socket path '" + socket + "' is too long for a Unix-domain socket";
    return std::nullopt;
  }
  return ServicePaths{directory, socket, directory + "/" + identity + ".lock", directory + "/" + identity + ".pid"};
}

}  // namespace stereoshift
