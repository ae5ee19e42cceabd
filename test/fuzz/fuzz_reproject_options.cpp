// libFuzzer target: this turns an arbitrary byte string into the words of a `stereoshift reproject`
// command line (one word per line), parses them with the command's real options and checks them
// with its real checker (cli/reproject_command.h), as the command does before it writes anything.
// The promise held: options the checker accepts are options the output can hold, so generating the
// shaders (which compiles and validates them) succeeds for every target; a value it cannot hold
// (a binding past glslang's layout fields, a near plane whose depth decoding reads inf, a block name
// that is no identifier) must be refused as an option error. A crash, a sanitizer report, an
// exception out of the parser other than CLI11's usage errors, or a failed generation is a finding.
#include "cli/reproject_command.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace stereoshift;
  if (size > 4096) return 0;  // a command line, not a file
  std::vector<std::string> words = {"stereoshift", "reproject", "-o", "unused-output-dir"};
  std::string word;
  for (size_t i = 0; i < size; ++i) {
    char c = static_cast<char>(data[i]);
    if (c == '\n' || c == '\0') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  if (words.size() > 64) return 0;
  std::vector<const char*> argv;
  for (const auto& w : words) argv.push_back(w.c_str());
  CLI::App app;
  ReprojectCliOptions options;
  addReprojectCommand(app, options);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
    return 0;  // a usage error, in CLI11's words
  }
  ParsedReproject parsed = parseReprojectOptions(options);
  if (!parsed.problems.empty()) return 0;  // refused as option errors: the promise kept
  for (TargetLanguage target : parsed.targets) {
    ReprojectOptions o = parsed.base;
    o.target = target;
    ReprojectResult result = generateReprojectShaders(o);
    if (!result.ok) {
      std::fprintf(stderr, "fuzz_reproject_options: options accepted that the output cannot hold:\n");
      for (size_t k = 4; k < words.size(); ++k) std::fprintf(stderr, "  %s\n", words[k].c_str());
      std::fprintf(stderr, "%s\n", result.diagnostics.format().c_str());
      std::abort();
    }
  }
  return 0;
}
