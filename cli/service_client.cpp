// The conversion service's client (see the header): finding or starting the server, one request,
// the answer relayed; every failure a quiet fall-back to the in-process conversion.
#include "cli/result_codec.h"
#include "cli/service_client.h"

#include "cli/fd_io.h"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>

namespace stereoshift {

namespace {

constexpr double kDefaultIdleSeconds = 300;
// How long a client waits for another one that is starting the server (it takes milliseconds).
constexpr double kLockWaitSeconds = 10;
// The answer may take the conversion's own time limit and this much more (the server's queue, the
// worker's set-up) before the client gives up on the server.
constexpr double kAnswerSlackSeconds = 60;

bool truthy(const char* value) {
  if (!value) return false;
  std::string v = value;
  for (char& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return v == "1" || v == "true" || v == "yes" || v == "on";
}

bool logging() { return truthy(std::getenv("STEREOSHIFT_SERVICE_LOG")); }

void note(const std::string& what) {
  if (logging()) std::cerr << "stereoshift: service: " << what << "\n";
}

double idleSeconds(const ServiceOptions& options) {
  if (options.idleSeconds) return *options.idleSeconds;
  if (const char* text = std::getenv("STEREOSHIFT_SERVICE_IDLE"); text && *text) {
    char* end = nullptr;
    double value = std::strtod(text, &end);
    if (end && *end == '\0' && value > 0) return value;
  }
  return kDefaultIdleSeconds;
}

int connectTo(const std::string& path) {
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
  while (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    if (errno == EINTR) continue;
    ::close(fd);
    return -1;
  }
  // The server must be this user's (the private directory says so already; this holds even for a
  // socket path that was swapped in some other way).
  ucred peer{};
  socklen_t size = sizeof peer;
  if (::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0 || peer.uid != ::geteuid()) {
    ::close(fd);
    return -1;
  }
  return fd;
}

int listenOn(const std::string& path) {
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(fd, SOMAXCONN) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Takes the start lock; -1 when it cannot be had in kLockWaitSeconds.
int takeLock(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0) return -1;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kLockWaitSeconds);
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if ((errno != EWOULDBLOCK && errno != EINTR) || std::chrono::steady_clock::now() > deadline) {
      ::close(fd);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return fd;
}

// A connection to the running server, starting one when none answers. Many commands of one build
// start at once: the first to take the lock binds the socket and starts the server; the others
// wait for the lock and then find the socket listening (connections queue while the server warms up).
int connectOrStart(const ServerSettings& settings, ServiceCommandLine entry) {
  if (int fd = connectTo(settings.paths.socket); fd >= 0) return fd;
  int lock = takeLock(settings.paths.lock);
  if (lock < 0) {
    note("could not take the start lock " + settings.paths.lock);
    return -1;
  }
  int fd = connectTo(settings.paths.socket);
  if (fd < 0) {
    // Under the lock, a socket nobody answers on is a dead server's (killed, or crashed): replaced.
    ::unlink(settings.paths.socket.c_str());
    int listening = listenOn(settings.paths.socket);
    if (listening < 0) {
      note("cannot listen on " + settings.paths.socket + ": " + std::strerror(errno));
    } else {
      bool started = startServer(listening, settings, entry);
      ::close(listening);
      if (started) {
        note("started a server on " + settings.paths.socket);
        fd = connectTo(settings.paths.socket);
      } else {
        ::unlink(settings.paths.socket.c_str());
        note("could not start a server");
      }
    }
  }
  ::close(lock);
  return fd;
}

bool readAllInput(std::string* bytes) {
  char buffer[65536];
  for (ssize_t n; (n = ::read(0, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes->append(buffer, static_cast<size_t>(n));
  }
  return true;
}

// Puts bytes already read from stdin back, for the in-process conversion: stdin becomes a memory
// file that holds them.
void restoreInput(const std::string& bytes) {
  int fd = ::memfd_create("stereoshift-stdin", MFD_CLOEXEC);
  if (fd < 0) return;
  for (size_t at = 0; at < bytes.size();) {
    ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
    if (n <= 0) break;
    at += static_cast<size_t>(n);
  }
  ::lseek(fd, 0, SEEK_SET);
  ::dup2(fd, 0);
  ::close(fd);
}

void writeAllTo(int fd, const std::string& bytes) { writeAll(fd, bytes.data(), bytes.size()); }

}  // namespace

void addServiceOptions(CLI::App& app, ServiceOptions& options) {
  auto* on = app.add_flag("--service", options.on,
                          "Convert through the warm per-user conversion server (started on first use; also STEREOSHIFT_SERVICE=1)");
  app.add_flag("--no-service", options.off, "Convert in this process, whatever STEREOSHIFT_SERVICE says")->excludes(on);
  app.add_option("--service-idle", options.idleSeconds,
                 "Seconds a conversion server started by this command waits for requests before it exits (default 300; also STEREOSHIFT_SERVICE_IDLE)")
      ->check(CLI::Validator(
          [](std::string& text) {
            char* end = nullptr;
            double value = std::strtod(text.c_str(), &end);
            return end && *end == '\0' && value > 0 ? std::string() : "'" + text + "' is not a number of seconds > 0";
          },
          "SECONDS"));
}

bool serviceWanted(const ServiceOptions& options) {
  if (runningInServiceWorker() || options.off) return false;
  return options.on || truthy(std::getenv("STEREOSHIFT_SERVICE"));
}

std::optional<int> runThroughService(int argc, char** argv, const ServiceOptions& options, const CliOptions& command,
                                     ServiceCommandLine entry) {
  auto identity = serverIdentity();
  if (!identity) {
    note("cannot identify this executable (/proc/self/exe); converting in-process");
    return std::nullopt;
  }
  std::string why;
  bool unsafe = false;
  auto paths = servicePaths(*identity, &why, &unsafe);
  if (!paths) {
    // A directory that is not private is a warning in any case: it is how another user could
    // reach this user's server, and it stays until someone fixes it.
    if (unsafe) std::cerr << "stereoshift: warning: not using the conversion service: " << why << "; converting in-process\n";
    else note(why + "; converting in-process");
    return std::nullopt;
  }

  ServiceRequest request;
  request.identity = *identity;
  for (int i = 0; i < argc; ++i) request.arguments.push_back(argv[i]);
  std::error_code ec;
  request.workingDirectory = std::filesystem::current_path(ec).string();
  if (ec) return std::nullopt;
  request.environment = serviceEnvironment();
  mode_t mask = ::umask(0);
  ::umask(mask);
  request.fileModeMask = static_cast<unsigned>(mask);
  bool readsInput = false;
  for (const auto& path : command.pipeline.empty() ? command.inputs : splitCommas(command.pipeline)) readsInput |= path == "-";
  for (const auto& path : command.inputs) readsInput |= path == "-";
  if (readsInput) {
    std::string bytes;
    if (!readAllInput(&bytes)) return std::nullopt;
    request.standardInput = std::move(bytes);
  }
  auto fallBack = [&](const std::string& what) -> std::optional<int> {
    note(what + "; converting in-process");
    if (request.standardInput) restoreInput(*request.standardInput);
    return std::nullopt;
  };

  ServerSettings settings{*identity, *paths, idleSeconds(options), command.t};
  int connection = connectOrStart(settings, entry);
  if (connection < 0) return fallBack("no server on " + paths->socket);
  std::string bytes;
  ServiceAnswer answer;
  double limit = command.timeoutSeconds > 0 ? command.timeoutSeconds + kAnswerSlackSeconds : 0;
  bool answered = sendMessage(connection, encodeServiceRequest(request)) && receiveMessage(connection, &bytes, limit) &&
                  decodeServiceAnswer(bytes, &answer);
  ::close(connection);
  if (!answered) return fallBack("the server on " + paths->socket + " gave no answer");
  note("served by the server on " + paths->socket);
  writeAllTo(1, answer.standardOutput);
  writeAllTo(2, answer.standardError);
  return answer.exitStatus;
}

}  // namespace stereoshift
