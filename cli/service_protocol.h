// What the conversion service's client and server share: the request and the answer as bytes on
// the Unix-domain socket, the tool identity that names a server (a rebuilt tool never talks to a
// server of its old build), and the private per-user directory the socket lives in.
//
// One connection carries one request (the command line, its cwd, the environment variables the
// CLI reads and, when an input is '-', standard input) and one answer (exit status, stdout and
// stderr bytes). Each message is an 8-byte little-endian length and that many bytes; the body opens
// with a magic string, so a wrong peer or a protocol change is an answer the client refuses.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

struct ServiceRequest {
  std::string identity;  // the client's serverIdentity(): the server refuses any other
  std::vector<std::string> arguments;  // argv, argv[0] included
  std::string workingDirectory;
  unsigned fileModeMask = 022;  // the client's umask: outputs get the modes they get in-process
  // Each variable the CLI reads (serviceEnvironmentNames) with its value, or none when unset.
  std::vector<std::pair<std::string, std::optional<std::string>>> environment;
  std::optional<std::string> standardInput;  // the bytes of stdin, when an input is '-'
};

struct ServiceAnswer {
  int exitStatus = 1;
  std::string standardOutput, standardError;
};

// Their bytes: encodeServiceRequest / encodeServiceAnswer and the decoders (result_codec.h).

// One length-prefixed message on a socket (a peer gone is `false`, not SIGPIPE). receiveMessage gives up (false) at end of stream, on a message
// larger than the protocol allows, or when `timeoutSeconds` (> 0) pass before it is complete.
bool sendMessage(int fd, const std::string& bytes);
bool receiveMessage(int fd, std::string* bytes, double timeoutSeconds);

// The environment variables a conversion reads: every STEREOSHIFT_* variable of this process,
// except the service's own switches, which mean nothing inside a worker.
std::vector<std::pair<std::string, std::optional<std::string>>> serviceEnvironment();
// Makes this process's STEREOSHIFT_* variables exactly the request's (set, or unset when absent).
void applyServiceEnvironment(const std::vector<std::pair<std::string, std::optional<std::string>>>& environment);

// A short hex name of this executable build: its resolved path, device, inode, size and
// modification time (not its bytes: hashing ~100 MB would cost more than the set-up the service
// saves). Copying or touching the binary gives another identity, hence another server.
std::optional<std::string> serverIdentity();

struct ServicePaths {
  std::string directory;  // private to the user: owned by them, no access for group or others
  std::string socket;     // <directory>/<identity>.sock
  std::string lock;       // <directory>/<identity>.lock: held while a server is started or stops
  std::string pidFile;    // <directory>/<identity>.pid: the running server's process id
};
// The paths for `identity`, creating the directory (mode 0700) when it is missing:
// $STEREOSHIFT_SERVICE_DIR, else $XDG_RUNTIME_DIR/stereoshift, else /tmp/stereoshift-<uid>. A
// directory that exists but is not a real directory owned by this user with mode 0700 (or
// stricter) is refused: `why` says what is wrong, `unsafe` whether it is a directory others could
// reach (rather than one that cannot be made or a socket path that is too long), and no server is used.
std::optional<ServicePaths> servicePaths(const std::string& identity, std::string* why, bool* unsafe);

}  // namespace stereoshift
