// The conversion service's client: turns a single-shader or --pipeline command line into a request
// to the per-user server of this tool build (started on first use), and the server's answer into
// this process's stdout, stderr and exit status. Whenever the service cannot answer (no socket
// directory that is private to the user, a server that cannot be started, reached or that answers
// wrongly), the command converts in-process instead: a build never fails because of the service.
//
// Asked for with --service or STEREOSHIFT_SERVICE=1 (--no-service wins over the variable);
// --service-idle / STEREOSHIFT_SERVICE_IDLE set how long a server it starts stays without requests.
// STEREOSHIFT_SERVICE_LOG=1 prints, on stderr, how each command was served.
#pragma once

#include "cli/cli_support.h"
#include "cli/service_server.h"

#include <optional>

namespace stereoshift {

struct ServiceOptions {
  bool on = false, off = false;       // --service, --no-service
  std::optional<double> idleSeconds;  // --service-idle
};

// Registers --service, --no-service and --service-idle on `app`.
void addServiceOptions(CLI::App& app, ServiceOptions& options);

// Whether this command goes through the service: never inside a service worker; else --no-service,
// --service, then STEREOSHIFT_SERVICE (1/true/yes/on).
bool serviceWanted(const ServiceOptions& options);

// Hands the command line (argc/argv, already parsed into `command`) to the server, starting one
// that runs `entry` (main's body) when none is running, and relays its answer. Returns the exit
// status, or none when the command must convert in-process (standard input, if the request took
// it, is then readable again).
std::optional<int> runThroughService(int argc, char** argv, const ServiceOptions& options, const CliOptions& command,
                                     ServiceCommandLine entry);

}  // namespace stereoshift
