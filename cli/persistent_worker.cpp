// Bazel's ways of calling the tool (params files, declared inputs, the persistent worker), turned
// into ordinary command lines. See persistent_worker.h for the contract.
#include "cli/persistent_worker.h"

#include "cli/cli_support.h"
#include "cli/fd_io.h"
#include "cli/result_codec.h"
#include "cli/worker_pool.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

constexpr const char* kDeclaredInputFlag = "--declared-input=";
constexpr const char* kPersistentWorkerFlag = "--persistent_worker";

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool readWholeFile(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return !in.bad();
}

int callEntry(const CommandLineEntry& entry, const std::vector<std::string>& args) {
  std::vector<std::string> storage = args;
  std::vector<char*> argv;
  for (auto& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  return entry(static_cast<int>(storage.size()), argv.data());
}

// The value of an option given as `--name VALUE` or `--name=VALUE` (the last one wins, as in CLI11).
std::optional<std::string> optionValue(const std::vector<std::string>& args, const std::string& name) {
  std::optional<std::string> value;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == name && i + 1 < args.size()) value = args[++i];
    else if (startsWith(args[i], (name + "=").c_str())) value = args[i].substr(name.size() + 1);
  }
  return value;
}

std::string normalPath(const std::string& path) { return fs::path(path).lexically_normal().string(); }

bool sendMessage(int fd, const std::string& message) {
  uint64_t size = message.size();
  return writeAll(fd, &size, sizeof size) && writeAll(fd, message.data(), message.size());
}

bool receiveMessage(int fd, std::string* message) {
  uint64_t size = 0;
  if (!readAll(fd, &size, sizeof size)) return false;
  message->assign(size, '\0');
  return readAll(fd, message->data(), size);
}

// Runs `entry` on `args` with standard output and standard error captured; returns the exit status.
int runCaptured(const CommandLineEntry& entry, const std::vector<std::string>& args, std::string* output) {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  FILE* capture = std::tmpfile();
  if (!capture) {
    *output = "stereoshift: error: persistent worker: cannot create a temporary file for the output\n";
    return 1;
  }
  int savedOut = ::dup(1), savedErr = ::dup(2);
  ::dup2(::fileno(capture), 1);
  ::dup2(::fileno(capture), 2);
  int status = runBazelAction(args, entry, std::cerr);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  ::dup2(savedOut, 1);
  ::dup2(savedErr, 2);
  ::close(savedOut);
  ::close(savedErr);
  output->clear();
  std::rewind(capture);
  char chunk[4096];
  for (size_t n; (n = std::fread(chunk, 1, sizeof chunk, capture)) > 0;) output->append(chunk, n);
  std::fclose(capture);
  return status;
}

// The long-lived process that runs the requests: forked once (and again after it crashed or was
// stopped), it converts in process (STEREOSHIFT_NO_FORK), so glslang's tables stay warm from one
// request to the next; the worker enforces each request's --timeout from outside.
class ConverterProcess {
 public:
  explicit ConverterProcess(const CommandLineEntry& entry) : entry_(entry) {}
  ~ConverterProcess() { stop(); }

  // Runs one request; `output` is what the command printed (or why it did not finish).
  int run(const std::vector<std::string>& args, std::string* output) {
    if (pid_ < 0 && !start()) {
      *output = "stereoshift: error: persistent worker: cannot start the converter process: " +
                std::string(std::strerror(errno)) + "\n1 error generated.\n";
      return 1;
    }
    std::string request = encodeCommandLine(args);
    double timeout = 300;  // the CLI's default --timeout
    if (auto given = optionValue(args, "--timeout")) timeout = std::atof(given->c_str());
    std::string reply;
    std::string failure;
    if (!sendMessage(toConverter_, request)) {
      failure = finish();
    } else if (!awaitReply(timeout)) {
      ::kill(pid_, SIGKILL);
      finish();
      char limit[32];
      std::snprintf(limit, sizeof limit, "%g", timeout);
      *output = std::string("stereoshift: error: conversion exceeded the ") + limit +
                " s time limit (--timeout); no output was written\n1 error generated.\n";
      return 1;
    } else if (!receiveMessage(fromConverter_, &reply)) {
      failure = finish();
    }
    if (!failure.empty()) {
      *output = "stereoshift: error: stereoshift " + failure + " while converting; no output was written\n1 error generated.\n";
      return 1;
    }
    int status = 1;
    if (!decodeCommandReply(reply, &status, output)) {
      finish();
      *output = "stereoshift: error: the converter process answered garbage; no output was written\n1 error generated.\n";
      return 1;
    }
    return status;
  }

 private:
  bool start() {
    int down[2], up[2];
    if (::pipe2(down, O_CLOEXEC) != 0) return false;
    if (::pipe2(up, O_CLOEXEC) != 0) {
      ::close(down[0]);
      ::close(down[1]);
      return false;
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    pid_t pid = ::fork();
    if (pid < 0) return false;
    if (pid == 0) {
      ::close(down[1]);
      ::close(up[0]);
      ::setenv("STEREOSHIFT_NO_FORK", "1", 1);
      std::string request;
      while (receiveMessage(down[0], &request)) {
        std::vector<std::string> args = decodeCommandLine(request);
        std::string output;
        int status = runCaptured(entry_, args, &output);
        if (!sendMessage(up[1], encodeCommandReply(status, output))) break;
      }
      ::_exit(0);  // no atexit handlers or static destructors: they belong to the worker
    }
    ::close(down[0]);
    ::close(up[1]);
    pid_ = pid;
    toConverter_ = down[1];
    fromConverter_ = up[0];
    return true;
  }

  // True when a reply is ready within `timeout` seconds (<= 0: no limit).
  bool awaitReply(double timeout) {
    using Clock = std::chrono::steady_clock;
    auto deadline = Clock::now() + std::chrono::duration<double>(timeout);
    while (true) {
      int waitMs = -1;
      if (timeout > 0) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return false;
        waitMs = static_cast<int>(std::min<long long>(left, 1 << 30));
      }
      pollfd p{fromConverter_, POLLIN, 0};
      int n = ::poll(&p, 1, waitMs);
      if (n > 0) return true;  // data, or the end of the pipe (read then fails and reports it)
      if (n < 0 && errno != EINTR) return true;
    }
  }

  // Closes the pipes, reaps the converter and says how it ended ("" when it ended normally).
  std::string finish() {
    if (pid_ < 0) return "";
    ::close(toConverter_);
    ::close(fromConverter_);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return describeExitStatus(status);
  }

  void stop() {
    if (pid_ < 0) return;
    ::close(toConverter_);  // the converter ends at the end of its requests
    toConverter_ = -1;
    finish();
  }

  const CommandLineEntry& entry_;
  pid_t pid_ = -1;
  int toConverter_ = -1;
  int fromConverter_ = -1;
};

// Reads the next JSON object from `in`: Bazel writes one per line, but any whitespace between and
// inside objects is accepted. Empty at the end of the input.
std::optional<std::string> readJsonObject(FILE* in) {
  std::string text;
  int depth = 0;
  bool inString = false, escaped = false;
  for (int c; (c = std::fgetc(in)) != EOF;) {
    if (depth == 0 && c != '{') {
      if (std::isspace(c)) continue;
      // Not an object: the rest of the line goes to the parser, which says so.
      for (; c != EOF && c != '\n'; c = std::fgetc(in)) text.push_back(static_cast<char>(c));
      return text;
    }
    text.push_back(static_cast<char>(c));
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{') {
      ++depth;
    } else if (c == '}' && --depth == 0) {
      return text;
    }
  }
  if (!text.empty()) return text;  // an object cut short: the parser reports it
  return std::nullopt;
}

}  // namespace

Result<std::vector<std::string>> expandArgsFiles(const std::vector<std::string>& args) {
  std::vector<std::string> expanded;
  for (const auto& a : args) {
    if (a.size() < 2 || a[0] != '@') {
      expanded.push_back(a);
      continue;
    }
    std::string text;
    if (!readWholeFile(a.substr(1), &text)) {
      return errorAt(0, 0, "cannot read argument file '" + a.substr(1) + "'");
    }
    for (size_t at = 0; at < text.size();) {
      size_t end = text.find('\n', at);
      std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      expanded.push_back(line);
      if (end == std::string::npos) break;
      at = end + 1;
    }
  }
  return expanded;
}

int runBazelAction(const std::vector<std::string>& args, const CommandLineEntry& entry, std::ostream& log) {
  std::vector<std::string> passed;
  std::set<std::string> declared;
  for (size_t i = 0; i < args.size(); ++i) {
    if (i > 0 && startsWith(args[i], kDeclaredInputFlag)) declared.insert(normalPath(args[i].substr(std::strlen(kDeclaredInputFlag))));
    else passed.push_back(args[i]);
  }
  std::optional<std::string> depfilePath = optionValue(passed, "--depfile");
  if (!declared.empty() && !depfilePath) {
    log << "stereoshift: error: --declared-input needs --depfile: the check of what was read reads the depfile\n";
    log.flush();
    printErrorSummary(1);
    return 2;
  }
  int status = callEntry(entry, passed);
  if (status != 0 || declared.empty()) return status;

  std::string text;
  std::optional<Depfile> depfile;
  if (readWholeFile(*depfilePath, &text)) depfile = parseDepfile(text);
  if (!depfile) {
    log << *depfilePath << ": error: cannot read the depfile the conversion wrote\n";
    log.flush();
    printErrorSummary(1);
    return 1;
  }
  int errors = 0;
  for (const auto& dependency : depfile->dependencies) {
    if (declared.count(normalPath(dependency))) continue;
    log << dependency
        << ": error: read by this action but not one of its declared inputs (add it to the rule's hdrs); no output was kept\n";
    ++errors;
  }
  if (!errors) return 0;
  std::error_code ec;
  for (const auto& target : depfile->targets) fs::remove(target, ec);
  fs::remove(*depfilePath, ec);
  log.flush();
  printErrorSummary(errors);
  return 1;
}

int runPersistentWorker(const CommandLineEntry& entry, int requestsFd, int responsesFd,
                        const std::vector<std::string>& startupArgs) {
  ::signal(SIGPIPE, SIG_IGN);  // a converter that died must not take the worker with it
  FILE* requests = ::fdopen(requestsFd, "r");
  if (!requests) {
    std::cerr << "stereoshift: error: persistent worker: cannot read the requests\n";
    return 2;
  }
  ConverterProcess converter(entry);
  while (std::optional<std::string> text = readJsonObject(requests)) {
    nlohmann::json request = nlohmann::json::parse(*text, nullptr, false);
    if (request.is_discarded() || !request.is_object() || !request.contains("arguments") || !request["arguments"].is_array()) {
      std::cerr << "stereoshift: error: persistent worker: not a JSON WorkRequest: " << text->substr(0, 200) << "\n";
      return 2;
    }
    std::vector<std::string> args{"stereoshift"};
    args.insert(args.end(), startupArgs.begin(), startupArgs.end());
    for (const auto& a : request["arguments"]) {
      if (!a.is_string()) {
        std::cerr << "stereoshift: error: persistent worker: a WorkRequest argument is not a string\n";
        return 2;
      }
      args.push_back(a.get<std::string>());
    }
    int requestId = request.contains("requestId") && request["requestId"].is_number_integer() ? request["requestId"].get<int>() : 0;

    std::string output;
    int status;
    if (auto expanded = expandArgsFiles(args)) {
      status = converter.run(*expanded, &output);
    } else {
      output = "stereoshift: error: " + expanded.error().message + "\n1 error generated.\n";
      status = 2;
    }
    nlohmann::json response = {{"exitCode", status}, {"output", output}, {"requestId", requestId}};
    std::string line = response.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    if (!writeAll(responsesFd, line.data(), line.size())) return 1;  // Bazel went away
  }
  return 0;
}

int runToolEntry(int argc, char** argv, const CommandLineEntry& entry) {
  std::vector<std::string> args(argv, argv + argc);
  bool worker = false, bazelAction = false;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == kPersistentWorkerFlag) worker = true;
    else if ((args[i].size() > 1 && args[i][0] == '@') || startsWith(args[i], kDeclaredInputFlag)) bazelAction = true;
  }
  if (worker) {
    // The requests and responses keep their own descriptors; the conversions get an empty
    // standard input and a standard output that can never write into the protocol (it goes to
    // standard error, which Bazel keeps in the worker's log).
    int requestsFd = ::dup(0), responsesFd = ::dup(1);
    int devNull = ::open("/dev/null", O_RDONLY);
    if (requestsFd < 0 || responsesFd < 0 || devNull < 0) {
      std::cerr << "stereoshift: error: persistent worker: cannot set up its descriptors\n";
      return 2;
    }
    ::dup2(devNull, 0);
    ::close(devNull);
    ::dup2(2, 1);
    std::vector<std::string> startupArgs;
    for (size_t i = 1; i < args.size(); ++i)
      if (args[i] != kPersistentWorkerFlag) startupArgs.push_back(args[i]);
    return runPersistentWorker(entry, requestsFd, responsesFd, startupArgs);
  }
  if (!bazelAction) return entry(argc, argv);
  Result<std::vector<std::string>> expanded = expandArgsFiles(args);
  if (!expanded) {
    std::cerr << "stereoshift: error: " << expanded.error().message << "\n";
    printErrorSummary(1);
    return 2;
  }
  return runBazelAction(*expanded, entry, std::cerr);
}

}  // namespace stereoshift
