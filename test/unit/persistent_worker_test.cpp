// The Bazel face of the CLI (cli/persistent_worker.h) with a stand-in for the command line: params
// files, the depfile reader, the declared-input check, and the worker loop (responses, captured
// output, one warm converter across requests, a crash or a hang costing only its request).
#include "cli/cli_support.h"
#include "cli/persistent_worker.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace stereoshift;

namespace {

fs::path scratchDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("stereoshift_persistent_worker_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The value of `name VALUE`; the last one wins, as in CLI11.
std::string argument(int argc, char** argv, const std::string& name) {
  std::string value;
  for (int i = 1; i + 1 < argc; ++i)
    if (argv[i] == name) value = argv[i + 1];
  return value;
}

// A stand-in for the command line: `--out FILE` writes FILE, `--depfile D --reads A,B` writes a
// depfile saying FILE was made from A and B, `--say TEXT` prints TEXT on both streams, `--pid`
// prints the process id, `--crash` dies of SIGABRT (not SIGSEGV: AddressSanitizer catches that one and exits 1 instead), `--hang` never returns.
int fakeCommandLine(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--crash") ::raise(SIGABRT);
    if (a == "--hang")
      while (true) ::pause();
    if (a == "--pid") std::cout << "pid " << ::getpid() << "\n";
  }
  std::string say = argument(argc, argv, "--say");
  if (!say.empty()) {
    std::cout << "out:" << say << "\n";
    std::cerr << "err:" << say << "\n";
    std::printf("printf:%s\n", say.c_str());
  }
  std::string out = argument(argc, argv, "--out");
  if (!out.empty()) writeText(out, "converted\n");
  std::string depfile = argument(argc, argv, "--depfile");
  if (!depfile.empty()) writeText(depfile, makeDepfile({out}, splitCommas(argument(argc, argv, "--reads"))));
  return argument(argc, argv, "--status").empty() ? 0 : std::stoi(argument(argc, argv, "--status"));
}

// Runs the worker loop on `requests` (one JSON object each) and returns its responses.
std::vector<nlohmann::json> runWorker(const std::vector<std::string>& requests, int* status,
                                      const std::vector<std::string>& startupArgs = {}) {
  int in[2];
  EXPECT_EQ(::pipe(in), 0);
  std::string all;
  for (const auto& r : requests) all += r + "\n";
  EXPECT_EQ(::write(in[1], all.data(), all.size()), static_cast<ssize_t>(all.size()));
  ::close(in[1]);
  FILE* out = std::tmpfile();
  *status = runPersistentWorker(fakeCommandLine, in[0], ::fileno(out), startupArgs);
  std::rewind(out);
  std::vector<nlohmann::json> responses;
  char line[65536];
  while (std::fgets(line, sizeof line, out)) responses.push_back(nlohmann::json::parse(line));
  std::fclose(out);
  return responses;
}

std::string request(const std::vector<std::string>& args, int id) {
  return nlohmann::json{{"arguments", args}, {"requestId", id}}.dump();
}

TEST(PersistentWorker, DepfileReadBackIsWhatMakeDepfileWrote) {
  std::vector<std::string> deps{"shaders/a b.vert", "inc/#odd.glsl", "cost$.h", "plain.frag"};
  auto parsed = parseDepfile(makeDepfile({"out/x y.vert", "out/z.frag"}, deps));
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->targets, (std::vector<std::string>{"out/x y.vert", "out/z.frag"}));
  std::sort(deps.begin(), deps.end());
  EXPECT_EQ(parsed->dependencies, deps);
  EXPECT_FALSE(parseDepfile("no colon here\n"));
}

TEST(PersistentWorker, ParamsFilesExpandOneArgumentPerLine) {
  fs::path dir = scratchDir("params");
  writeText(dir / "args", "--target\nglsl\r\nwith space.vert\n\n-o\nout dir\n");
  auto expanded = expandArgsFiles({"stereoshift", "-x", "@" + (dir / "args").string(), "last"});
  ASSERT_TRUE(expanded) << expanded.error().format();
  EXPECT_EQ(*expanded, (std::vector<std::string>{"stereoshift", "-x", "--target", "glsl", "with space.vert", "", "-o",
                                                  "out dir", "last"}));
  auto missing = expandArgsFiles({"stereoshift", "@" + (dir / "missing").string()});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("cannot read argument file"), std::string::npos);
  fs::remove_all(dir);
}

TEST(PersistentWorker, AnUndeclaredReadFailsTheActionAndRemovesItsOutputs) {
  fs::path dir = scratchDir("declared");
  std::string out = (dir / "a.vert").string(), dep = (dir / "a.d").string();
  std::ostringstream log;
  // Everything read was declared ("./" spellings are the same file).
  EXPECT_EQ(runBazelAction({"stereoshift", "--out", out, "--depfile", dep, "--reads", "src/a.vert,./inc/common.glsl",
                            "--declared-input=src/a.vert", "--declared-input=inc/common.glsl"},
                           fakeCommandLine, log),
            0)
      << log.str();
  EXPECT_TRUE(fs::exists(out));

  log.str("");
  EXPECT_EQ(runBazelAction({"stereoshift", "--out", out, "--depfile", dep, "--reads", "src/a.vert,inc/secret.glsl",
                            "--declared-input=src/a.vert"},
                           fakeCommandLine, log),
            1);
  EXPECT_NE(log.str().find("inc/secret.glsl: error: read by this action but not one of its declared inputs"), std::string::npos)
      << log.str();
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dep));

  log.str("");
  EXPECT_EQ(runBazelAction({"stereoshift", "--out", out, "--declared-input=src/a.vert"}, fakeCommandLine, log), 2);
  EXPECT_NE(log.str().find("--declared-input needs --depfile"), std::string::npos);

  // Without declared inputs the command runs as it is, status and all.
  EXPECT_EQ(runBazelAction({"stereoshift", "--status", "3"}, fakeCommandLine, log), 3);
  fs::remove_all(dir);
}

TEST(PersistentWorker, AnswersEachRequestWithItsStatusOutputAndId) {
  int status = -1;
  auto responses = runWorker({request({"--say", "hello"}, 7), request({"--status", "1"}, 8),
                              R"({"arguments": ["--say", "no id"]})"},
                             &status);
  EXPECT_EQ(status, 0);
  ASSERT_EQ(responses.size(), 3u);
  EXPECT_EQ(responses[0]["requestId"], 7);
  EXPECT_EQ(responses[0]["exitCode"], 0);
  std::string output = responses[0]["output"];
  EXPECT_NE(output.find("out:hello"), std::string::npos) << output;
  EXPECT_NE(output.find("err:hello"), std::string::npos) << output;
  EXPECT_NE(output.find("printf:hello"), std::string::npos) << output;
  EXPECT_EQ(responses[1]["requestId"], 8);
  EXPECT_EQ(responses[1]["exitCode"], 1);
  EXPECT_EQ(responses[1]["output"], "");  // nothing of the first request's output left over
  EXPECT_EQ(responses[2]["requestId"], 0);
}

TEST(PersistentWorker, OneConverterServesEveryRequestUntilOneCrashes) {
  int status = -1;
  auto responses = runWorker({request({"--pid"}, 1), request({"--pid"}, 2), request({"--crash"}, 3), request({"--pid"}, 4)},
                             &status);
  EXPECT_EQ(status, 0);
  ASSERT_EQ(responses.size(), 4u);
  std::string first = responses[0]["output"], second = responses[1]["output"], afterCrash = responses[3]["output"];
  EXPECT_EQ(first.rfind("pid ", 0), 0u) << first;
  EXPECT_EQ(first, second);  // the same warm process
  EXPECT_NE(first, "pid " + std::to_string(::getpid()) + "\n");  // and not the worker itself
  EXPECT_EQ(responses[2]["exitCode"], 1);
  std::string crash = responses[2]["output"];
  EXPECT_NE(crash.find("crashed (signal 6, SIGABRT)"), std::string::npos) << crash;
  EXPECT_EQ(responses[3]["exitCode"], 0);
  EXPECT_NE(afterCrash, first);  // a fresh converter
}

TEST(PersistentWorker, AHangingRequestIsStoppedAtItsTimeout) {
  int status = -1;
  auto responses = runWorker({request({"--hang", "--timeout", "0.2"}, 1), request({"--say", "after"}, 2)}, &status);
  ASSERT_EQ(responses.size(), 2u);
  EXPECT_EQ(responses[0]["exitCode"], 1);
  std::string timedOut = responses[0]["output"];
  EXPECT_NE(timedOut.find("exceeded the 0.2 s time limit (--timeout)"), std::string::npos) << timedOut;
  EXPECT_EQ(responses[1]["exitCode"], 0);
}

TEST(PersistentWorker, StartupArgumentsComeBeforeEachRequestsOwn) {
  int status = -1;
  auto responses = runWorker({request({}, 1), request({"--status", "4"}, 2)}, &status, {"--say", "startup", "--status", "3"});
  ASSERT_EQ(responses.size(), 2u);
  EXPECT_NE(std::string(responses[0]["output"]).find("err:startup"), std::string::npos);
  EXPECT_EQ(responses[0]["exitCode"], 3);
  EXPECT_EQ(responses[1]["exitCode"], 4);  // the request's own option wins, as the later one
}

TEST(PersistentWorker, SomethingThatIsNotAWorkRequestEndsTheWorker) {
  int status = -1;
  auto responses = runWorker({request({"--say", "x"}, 1), "[1, 2]"}, &status);
  EXPECT_EQ(status, 2);
  EXPECT_EQ(responses.size(), 1u);
}

}  // namespace
