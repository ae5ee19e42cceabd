// The conversion service's server: turns a listening Unix-domain socket into a long-lived,
// detached per-user process that keeps glslang initialised (its built-in tables built for the
// common dialects) and runs each request in a worker forked from that warm state.
//
// A worker runs the request exactly as the command line would run in-process: it calls the same
// entry main() calls, with the client's argv, cwd, STEREOSHIFT_* variables and stdin, and hands
// back the exit status and the stdout and stderr bytes. Outputs, depfiles and the crash and
// timeout isolation of the conversion are the CLI's own (the conversion runs in a child of the
// worker, as in-process it runs in a child of the tool), so a shader that crashes glslang costs
// that child, is reported by the worker in the CLI's words, and never touches the server. A worker
// that dies itself answers nothing, and the client converts in-process.
#pragma once

#include "cli/service_protocol.h"
#include "transpiler/transpile_options.h"

#include <string>

namespace stereoshift {

// The CLI's entry (main's body): what a worker runs for each request.
using ServiceCommandLine = int (*)(int argc, char** argv);

struct ServerSettings {
  std::string identity;
  ServicePaths paths;
  double idleSeconds = 300;  // the server exits after this long without a request
  // The options of the command that started the server: the warm-up converts with them (the
  // target environment and SPIR-V version choose glslang's tables), as a build's commands share them.
  TranspileOptions warmOptions;
};

// Starts the server on `listeningFd` (bound and listening already, so that clients can connect
// and queue from this moment on) in a detached process (a new session, double-forked, standard
// streams on /dev/null, no other descriptor of the caller). Returns false when it could not fork.
// The caller keeps its copy of `listeningFd` and closes it.
bool startServer(int listeningFd, const ServerSettings& settings, ServiceCommandLine entry);

// True inside a worker: the CLI then converts in-process and never asks the service again.
bool runningInServiceWorker();

}  // namespace stereoshift
