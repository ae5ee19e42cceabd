// The conversion service's server process (see the header): warm-up, the accept loop, forked
// workers, idle exit.
#include "cli/result_codec.h"
#include "cli/service_server.h"

#include "transpiler/frontend/front_end.h"
#include "transpiler/stereoshift.h"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace stereoshift {

namespace {

bool inWorker = false;

using Clock = std::chrono::steady_clock;

// A worker that gets no complete request in this time is talking to something that is not a client.
constexpr double kRequestTimeoutSeconds = 30;

// One warm-up conversion: a minimal pipeline of one dialect. glslang builds its built-in symbol
// tables once per dialect (version, profile, source language, target environment) in each process,
// ~100 ms of a cold command's ~130 ms; converting these in the server before it forks workers
// gives every worker the tables for free (copy-on-write). Most used first, since requests are
// served between steps: GLSL for Vulkan and OpenGL in the versions tutorials and SDK samples use,
// ESSL, HLSL. A dialect not listed only costs its first command in each worker the set-up.
struct WarmUp {
  const char* name;  // the file name: its extension gives the stage and language
  const char* text;
};
const WarmUp kWarmUps[] = {
    {"warm.vert", "#version 450\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 450\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert.hlsl", "float4 main(float4 p : POSITION) : SV_Position { return p; }\n"},
    {"warm.frag.hlsl", "float4 main() : SV_Target { return 1.0; }\n"},
    {"warm.comp", "#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n"},
    {"warm.vert", "#version 460\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 460\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 330 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert", "#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 300 es\nprecision mediump float;\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert", "#version 310 es\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 310 es\nprecision mediump float;\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert", "#version 410 core\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 410 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert", "#version 430 core\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 430 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
    {"warm.vert", "#version 100\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 100\nprecision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }\n"},
    {"warm.vert", "#version 120\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 120\nvoid main() { gl_FragColor = vec4(1.0); }\n"},
    {"warm.vert", "#version 150\nvoid main() { gl_Position = vec4(0.0); }\n"},
    {"warm.frag", "#version 150\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"},
};

void appendLog(const ServicePaths& paths, const std::string& line) {
  int fd = ::open((paths.directory + "/service.log").c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0) return;
  std::string text = line + "\n";
  (void)!::write(fd, text.data(), text.size());
  ::close(fd);
}

// The inode the socket path had when this server bound it: a path that names another inode (or
// none) belongs to a newer server, or was removed; this server then leaves.
ino_t inodeOf(const std::string& path) {
  struct stat s {};
  return ::lstat(path.c_str(), &s) == 0 ? s.st_ino : 0;
}

// A memory file holding `bytes`, positioned at its start; -1 on failure.
int memoryFile(const char* name, const std::string& bytes) {
  int fd = ::memfd_create(name, MFD_CLOEXEC);
  if (fd < 0) return -1;
  size_t at = 0;
  while (at < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
    if (n <= 0) {
      ::close(fd);
      return -1;
    }
    at += static_cast<size_t>(n);
  }
  ::lseek(fd, 0, SEEK_SET);
  return fd;
}

std::string readWhole(int fd) {
  std::string bytes;
  ::lseek(fd, 0, SEEK_SET);
  char buffer[65536];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    bytes.append(buffer, static_cast<size_t>(n));
  }
  return bytes;
}

// A worker: one request, run through the CLI's own entry, answered; then the process ends.
[[noreturn]] void serveConnection(int connection, const ServerSettings& settings, ServiceCommandLine entry) {
  inWorker = true;
  // The signal dispositions of a command line, not of the server.
  ::signal(SIGPIPE, SIG_DFL);
  ::signal(SIGHUP, SIG_DFL);
  ::signal(SIGINT, SIG_DFL);
  std::string bytes;
  ServiceRequest request;
  // Nothing is answered to a request this server must not run (another tool build, a cwd it cannot
  // enter): the client sees the connection close and converts in-process.
  if (!receiveMessage(connection, &bytes, kRequestTimeoutSeconds) || !decodeServiceRequest(bytes, &request) ||
      request.identity != settings.identity || ::chdir(request.workingDirectory.c_str()) != 0)
    ::_exit(0);
  applyServiceEnvironment(request.environment);
  ::umask(static_cast<mode_t>(request.fileModeMask));

  int input = request.standardInput ? memoryFile("stereoshift-stdin", *request.standardInput) : ::open("/dev/null", O_RDONLY);
  int output = ::memfd_create("stereoshift-stdout", MFD_CLOEXEC);
  int error = ::memfd_create("stereoshift-stderr", MFD_CLOEXEC);
  if (input < 0 || output < 0 || error < 0 || ::dup2(input, 0) < 0 || ::dup2(output, 1) < 0 || ::dup2(error, 2) < 0)
    ::_exit(0);

  std::vector<char*> argv;
  for (auto& argument : request.arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  int status = entry(static_cast<int>(request.arguments.size()), argv.data());
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);

  ServiceAnswer answer;
  answer.exitStatus = status & 0xff;
  answer.standardOutput = readWhole(output);
  answer.standardError = readWhole(error);
  sendMessage(connection, encodeServiceAnswer(answer));
  ::_exit(0);
}

class Server {
 public:
  Server(int listening, const ServerSettings& settings, ServiceCommandLine entry)
      : listening_(listening), settings_(settings), entry_(entry) {}

  [[noreturn]] void run() {
    socketInode_ = inodeOf(settings_.paths.socket);
    writePidFile();
    appendLog(settings_.paths, "server " + std::to_string(::getpid()) + " started (identity " + settings_.identity + ")");
    ensureGlslangInitialized();
    lastRequest_ = Clock::now();
    for (const WarmUp& w : kWarmUps) {
      warm(w);
      acceptPending(0);  // requests that queued during this step get the tables warmed so far
    }
    while (true) {
      reapWorkers();
      if (inodeOf(settings_.paths.socket) != socketInode_) leave("its socket was removed or replaced", false);
      double idle = std::chrono::duration<double>(Clock::now() - lastRequest_).count();
      // Workers in flight need no server: each holds its own connection and ends on its own.
      if (idle >= settings_.idleSeconds) leave("idle", true);
      double wait = std::max(0.0, settings_.idleSeconds - idle);
      acceptPending(static_cast<int>(std::min(1000.0, wait * 1000) + 1));
    }
  }

 private:
  void writePidFile() {
    std::string temporary = settings_.paths.pidFile + ".tmp" + std::to_string(::getpid());
    int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0) return;
    std::string text = std::to_string(::getpid()) + "\n";
    (void)!::write(fd, text.data(), text.size());
    ::close(fd);
    ::rename(temporary.c_str(), settings_.paths.pidFile.c_str());
  }

  void warm(const WarmUp& w) {
    TranspileOptions options = settings_.warmOptions;
    // The warm-up shaders say their own stage and language; nothing of them is checked or printed.
    options.stage.reset();
    options.language.reset();
    options.entryPoint = "main";
    options.verify = false;
    options.printAll = false;
    options.validateEach = false;
    options.stageExtensions.clear();
    (void)transpile(SourceFile{w.name, w.text}, options);
  }

  // Accepts every connection that is waiting (after up to `timeoutMs` for the first one).
  void acceptPending(int timeoutMs) {
    for (int wait = timeoutMs;; wait = 0) {
      pollfd p{listening_, POLLIN, 0};
      int ready = ::poll(&p, 1, wait);
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0) return;
      int connection = ::accept4(listening_, nullptr, nullptr, SOCK_CLOEXEC);
      if (connection < 0) return;
      lastRequest_ = Clock::now();
      // Only this user's processes are served (the directory already keeps others out; this holds
      // even if its mode were changed while the server runs).
      ucred peer{};
      socklen_t size = sizeof peer;
      if (::getsockopt(connection, SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0 || peer.uid != ::geteuid()) {
        ::close(connection);
        continue;
      }
      pid_t pid = ::fork();
      if (pid == 0) {
        ::close(listening_);
        serveConnection(connection, settings_, entry_);
      }
      ::close(connection);
      if (pid > 0) ++workers_;
    }
  }

  void reapWorkers() {
    while (::waitpid(-1, nullptr, WNOHANG) > 0) --workers_;
  }

  // Stops serving. With `ownSocket`, under the start lock (so no client starts a server meanwhile):
  // the socket is removed first, then the connections that queued before are still served.
  [[noreturn]] void leave(const std::string& why, bool ownSocket) {
    int lock = -1;
    if (ownSocket) {
      lock = ::open(settings_.paths.lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
      if (lock >= 0) ::flock(lock, LOCK_EX);
      if (inodeOf(settings_.paths.socket) == socketInode_) {
        ::unlink(settings_.paths.socket.c_str());
        ::unlink(settings_.paths.pidFile.c_str());
      }
      acceptPending(0);
    }
    ::close(listening_);
    appendLog(settings_.paths, "server " + std::to_string(::getpid()) + " exits: " + why);
    if (lock >= 0) ::close(lock);
    ::_exit(0);
  }

  int listening_;
  const ServerSettings& settings_;
  ServiceCommandLine entry_;
  ino_t socketInode_ = 0;
  int workers_ = 0;
  Clock::time_point lastRequest_;
};

// Closes every descriptor but `keep` (and the standard three, which go to /dev/null): a server that
// held a Ninja job's output pipe would keep Ninja waiting for the job to end.
void detachDescriptors(int keep) {
  std::vector<int> open;
  if (DIR* d = ::opendir("/proc/self/fd")) {
    while (dirent* e = ::readdir(d)) {
      int fd = std::atoi(e->d_name);
      if (e->d_name[0] != '.' && fd > 2 && fd != keep) open.push_back(fd);
    }
    ::closedir(d);
  } else {
    for (int fd = 3; fd < 1024; ++fd)
      if (fd != keep) open.push_back(fd);
  }
  for (int fd : open) ::close(fd);
  int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    if (null > 2 && null != keep) ::close(null);
  }
}

}  // namespace

bool runningInServiceWorker() { return inWorker; }

bool startServer(int listeningFd, const ServerSettings& settings, ServiceCommandLine entry) {
  pid_t child = ::fork();
  if (child < 0) return false;
  if (child == 0) {
    // A new session, then a second fork: the server is no session leader, has no controlling
    // terminal, and is nobody's child that waits for it (init reaps it).
    ::setsid();
    pid_t server = ::fork();
    if (server != 0) ::_exit(server < 0 ? 1 : 0);
    detachDescriptors(listeningFd);
    (void)!::chdir("/");
    ::signal(SIGPIPE, SIG_IGN);
    ::signal(SIGHUP, SIG_IGN);
    ::signal(SIGINT, SIG_IGN);  // a Ctrl-C in the terminal of the build that started it is not for the server
    ::signal(SIGCHLD, SIG_DFL);
    Server(listeningFd, settings, entry).run();
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace stereoshift
