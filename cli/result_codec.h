// The one codec for what the CLI's processes hand each other: the forked conversion child of the
// single-shader command, a `build` worker, the conversion service (request and answer) and the
// persistent worker's converter process (command line and reply). Everything is a sequence of
// length-prefixed byte strings (putString / getString), so outputs travel as raw bytes (SPIR-V is
// binary) and text needs no escaping; each message below is one fixed order of such strings. The
// transports (pipes, the service's socket) frame whole messages themselves.
#pragma once

#include "cli/build_job.h"
#include "cli/output_commit.h"
#include "cli/service_protocol.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace stereoshift {

// ---- the primitives -----------------------------------------------------------------------------

// Appends `s` as its 8-byte (host order) length and its bytes.
void putString(std::string& wire, const std::string& s);
// Reads one string at `at` and advances `at`; false when `wire` ends early.
bool getString(const std::string& wire, size_t& at, std::string* s);

// ---- the single-shader conversion's child -------------------------------------------------------

// What the conversion child hands back to the parent, which writes: the error count so far, the
// outputs (written only when there is no error), the report and the depfile text.
struct ConversionRun {
  int errors = 0;
  std::vector<PendingOutput> outputs;
  bool hasReport = false;
  nlohmann::json report;
  std::string depfileText;
};
// The report travels as JSON text; the outputs as raw bytes.
std::string encodeConversionRun(const ConversionRun& run);
bool decodeConversionRun(const std::string& wire, ConversionRun* run);

// ---- a build worker's job result ----------------------------------------------------------------

// A JSON head (errors, log, reports, dependencies, key, replayable, the output count), then the
// outputs. reportTexts and reportFacts are not sent: they describe up-to-date jobs, which no
// worker converts.
std::string encodeJobResult(const JobResult& result);
bool decodeJobResult(const std::string& wire, JobResult* result);

// ---- the conversion service ---------------------------------------------------------------------

// Each body opens with a magic string naming the protocol's version: an old client and a new
// server refuse each other's bytes. Decoding fails on trailing bytes too.
std::string encodeServiceRequest(const ServiceRequest& request);
bool decodeServiceRequest(const std::string& wire, ServiceRequest* request);
std::string encodeServiceAnswer(const ServiceAnswer& answer);
bool decodeServiceAnswer(const std::string& wire, ServiceAnswer* answer);

// ---- the persistent worker's converter process --------------------------------------------------

// A request is the command line, one string per argument; decoding keeps the arguments read
// before any that is cut short.
std::string encodeCommandLine(const std::vector<std::string>& args);
std::vector<std::string> decodeCommandLine(const std::string& wire);
// The reply: the exit status and everything the command printed.
std::string encodeCommandReply(int status, const std::string& output);
bool decodeCommandReply(const std::string& wire, int* status, std::string* output);

}  // namespace stereoshift
