// The one codec of the CLI's processes (see result_codec.h): every message of the conversion
// child, the build worker, the conversion service and the persistent worker's converter, each
// written and read here in the same order.
#include "cli/result_codec.h"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace stereoshift {

namespace {

// A new protocol gets a new string: an old client and a new server refuse each other's bytes.
constexpr const char* kRequestMagic = "stereoshift-service-request-1";
constexpr const char* kAnswerMagic = "stereoshift-service-answer-1";

// A decimal number written as a string; false when it is not one.
bool getNumber(const std::string& wire, size_t& at, long long* value) {
  std::string text;
  if (!getString(wire, at, &text) || text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *value = std::strtoll(text.c_str(), &end, 10);
  return errno == 0 && end && *end == '\0';
}

}  // namespace

void putString(std::string& wire, const std::string& s) {
  uint64_t size = s.size();
  wire.append(reinterpret_cast<const char*>(&size), sizeof size);
  wire += s;
}

bool getString(const std::string& wire, size_t& at, std::string* s) {
  uint64_t size = 0;
  if (wire.size() - at < sizeof size) return false;
  std::memcpy(&size, wire.data() + at, sizeof size);
  at += sizeof size;
  if (wire.size() - at < size) return false;
  *s = wire.substr(at, size);
  at += size;
  return true;
}

// ---- the single-shader conversion's child -------------------------------------------------------

std::string encodeConversionRun(const ConversionRun& run) {
  std::string wire;
  putString(wire, std::to_string(run.errors));
  putString(wire, run.hasReport ? run.report.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) : "");
  putString(wire, run.depfileText);
  putString(wire, std::to_string(run.outputs.size()));
  for (const auto& o : run.outputs) {
    putString(wire, o.path);
    putString(wire, o.bytes);
  }
  return wire;
}

bool decodeConversionRun(const std::string& wire, ConversionRun* run) {
  size_t at = 0;
  std::string errors, report, count;
  if (!getString(wire, at, &errors) || !getString(wire, at, &report) || !getString(wire, at, &run->depfileText) ||
      !getString(wire, at, &count))
    return false;
  run->errors = std::atoi(errors.c_str());
  run->hasReport = !report.empty();
  if (run->hasReport) run->report = nlohmann::json::parse(report, nullptr, false);
  run->outputs.resize(static_cast<size_t>(std::strtoull(count.c_str(), nullptr, 10)));
  for (auto& o : run->outputs)
    if (!getString(wire, at, &o.path) || !getString(wire, at, &o.bytes)) return false;
  return true;
}

// ---- a build worker's job result ----------------------------------------------------------------

std::string encodeJobResult(const JobResult& r) {
  nlohmann::json head = {{"errors", r.errors}, {"log", r.log}, {"reports", r.reports},
                         {"dependencies", r.dependencies}, {"key", r.key}, {"outputs", r.outputs.size()},
                         {"replayable", r.replayable}};
  std::string out;
  putString(out, head.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  for (const auto& o : r.outputs) putString(out, o);
  return out;
}

bool decodeJobResult(const std::string& in, JobResult* r) {
  size_t at = 0;
  std::string text;
  if (!getString(in, at, &text)) return false;
  nlohmann::json head = nlohmann::json::parse(text, nullptr, false);
  if (head.is_discarded()) return false;
  r->errors = head.value("errors", 1);
  r->log = head.value("log", "");
  r->reports = head.value("reports", nlohmann::json::array());
  r->dependencies = head.value("dependencies", std::vector<std::string>{});
  r->key = head.value("key", "");
  r->replayable = head.value("replayable", false);
  size_t count = head.value("outputs", size_t{0});
  r->outputs.resize(count);
  for (auto& o : r->outputs)
    if (!getString(in, at, &o)) return false;
  return true;
}

// ---- the conversion service ---------------------------------------------------------------------

std::string encodeServiceRequest(const ServiceRequest& r) {
  std::string wire;
  putString(wire, kRequestMagic);
  putString(wire, r.identity);
  putString(wire, std::to_string(r.arguments.size()));
  for (const auto& a : r.arguments) putString(wire, a);
  putString(wire, r.workingDirectory);
  putString(wire, std::to_string(r.fileModeMask));
  putString(wire, std::to_string(r.environment.size()));
  for (const auto& [name, value] : r.environment) {
    putString(wire, name);
    putString(wire, value ? "1" : "0");
    putString(wire, value.value_or(""));
  }
  putString(wire, r.standardInput ? "1" : "0");
  putString(wire, r.standardInput.value_or(""));
  return wire;
}

bool decodeServiceRequest(const std::string& wire, ServiceRequest* r) {
  size_t at = 0;
  std::string magic, flag, text;
  long long count = 0;
  if (!getString(wire, at, &magic) || magic != kRequestMagic) return false;
  if (!getString(wire, at, &r->identity) || !getNumber(wire, at, &count) || count < 1) return false;
  r->arguments.clear();
  for (long long i = 0; i < count; ++i) {
    if (!getString(wire, at, &text)) return false;
    r->arguments.push_back(text);
  }
  long long mask = 0;
  if (!getString(wire, at, &r->workingDirectory) || !getNumber(wire, at, &mask) || mask < 0 || mask > 0777) return false;
  r->fileModeMask = static_cast<unsigned>(mask);
  if (!getNumber(wire, at, &count) || count < 0) return false;
  r->environment.clear();
  for (long long i = 0; i < count; ++i) {
    std::string name;
    if (!getString(wire, at, &name) || !getString(wire, at, &flag) || !getString(wire, at, &text)) return false;
    r->environment.emplace_back(name, flag == "1" ? std::optional<std::string>(text) : std::nullopt);
  }
  if (!getString(wire, at, &flag) || !getString(wire, at, &text)) return false;
  r->standardInput = flag == "1" ? std::optional<std::string>(text) : std::nullopt;
  return at == wire.size();
}

std::string encodeServiceAnswer(const ServiceAnswer& a) {
  std::string wire;
  putString(wire, kAnswerMagic);
  putString(wire, std::to_string(a.exitStatus));
  putString(wire, a.standardOutput);
  putString(wire, a.standardError);
  return wire;
}

bool decodeServiceAnswer(const std::string& wire, ServiceAnswer* a) {
  size_t at = 0;
  std::string magic;
  long long status = 0;
  if (!getString(wire, at, &magic) || magic != kAnswerMagic || !getNumber(wire, at, &status)) return false;
  if (status < 0 || status > 255) return false;
  a->exitStatus = static_cast<int>(status);
  return getString(wire, at, &a->standardOutput) && getString(wire, at, &a->standardError) && at == wire.size();
}

// ---- the persistent worker's converter process --------------------------------------------------

std::string encodeCommandLine(const std::vector<std::string>& args) {
  std::string wire;
  for (const auto& a : args) putString(wire, a);
  return wire;
}

std::vector<std::string> decodeCommandLine(const std::string& wire) {
  std::vector<std::string> args;
  size_t at = 0;
  for (std::string a; at < wire.size() && getString(wire, at, &a);) args.push_back(a);
  return args;
}

std::string encodeCommandReply(int status, const std::string& output) {
  std::string wire;
  putString(wire, std::to_string(status));
  putString(wire, output);
  return wire;
}

bool decodeCommandReply(const std::string& wire, int* status, std::string* output) {
  size_t at = 0;
  std::string text;
  if (!getString(wire, at, &text) || !getString(wire, at, output)) return false;
  *status = std::atoi(text.c_str());
  return true;
}

}  // namespace stereoshift
