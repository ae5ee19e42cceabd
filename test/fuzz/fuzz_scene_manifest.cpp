// libFuzzer target: this turns an arbitrary byte string into a scene manifest (TOML) and loads it
// with stereoshift::loadSceneManifest (cli/scene_manifest.h) with the CLI's real conversion options
// as the accepted keys and their real checker, as `stereoshift build scene.toml` does.
// A crash, an ASan/UBSan report, an exception out of the loader, or an error not in
// `file:line:col: error: message` form is a finding.
#include "cli/cli_support.h"
#include "cli/scene_manifest.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace stereoshift;

std::vector<std::string> conversionOptionKeys() {
  CliOptions scratch;
  CLI::App app;
  addConversionOptions(app, scratch);
  std::vector<std::string> keys;
  for (const CLI::Option* option : app.get_options())
    for (const auto& name : option->get_lnames()) keys.push_back(name);
  return keys;
}

// The words of one option checked the way the CLI checks its own command line.
std::string checkOptionWords(const std::vector<std::string>& words) {
  CliOptions scratch;
  CLI::App app;
  addConversionOptions(app, scratch);
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  if (auto error = finishOptions(scratch)) return *error;
  return "";
}

// The loader reads a file: each fuzzing process writes its input to a file of its own.
const std::filesystem::path& manifestPath() {
  static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                            ("stereoshift-fuzz-" + std::to_string(::getpid())) / "scene.toml";
  static const bool made = std::filesystem::create_directories(path.parent_path()) || true;
  (void)made;
  return path;
}

// "<file>:<line>:<col>: error: <message>" on one line: a non-empty file, digits, a non-empty message.
bool isLocatedError(const std::string& e) {
  if (e.find('\n') != std::string::npos) return false;
  const std::string marker = ": error: ";
  for (size_t at = e.find(marker); at != std::string::npos; at = e.find(marker, at + 1)) {
    if (at + marker.size() >= e.size()) break;  // empty message
    auto digitsBefore = [&](size_t end) {  // start of the digit run ending at `end`, or npos if none
      size_t begin = end;
      while (begin > 0 && e[begin - 1] >= '0' && e[begin - 1] <= '9') --begin;
      return begin == end ? std::string::npos : begin;
    };
    size_t column = digitsBefore(at);
    if (column == std::string::npos || column == 0 || e[column - 1] != ':') continue;
    size_t line = digitsBefore(column - 1);
    if (line == std::string::npos || line < 2 || e[line - 1] != ':') continue;
    if (e.substr(0, line - 1).find('\r') == std::string::npos) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::vector<std::string> keys = conversionOptionKeys();
  const std::filesystem::path& file = manifestPath();
  if (FILE* out = std::fopen(file.c_str(), "wb")) {
    if (size) std::fwrite(data, 1, size, out);
    std::fclose(out);
  } else {
    std::perror("fuzz_scene_manifest: cannot write the manifest");
    std::abort();
  }

  SceneManifest manifest;
  std::vector<std::string> errors;
  bool ok = loadSceneManifest(file, keys, checkOptionWords, &manifest, &errors);
  if (ok != errors.empty()) {
    std::fprintf(stderr, "fuzz_scene_manifest: loader returned %s with %zu errors\n", ok ? "true" : "false",
                 errors.size());
    std::abort();
  }
  for (const auto& e : errors)
    if (!isLocatedError(e)) {
      std::fprintf(stderr, "fuzz_scene_manifest: error not in file:line:col form: %s\n", e.c_str());
      std::abort();
    }
  return 0;
}
