// How the CLI commits what it made: an output is written through a temporary file renamed into
// place (never a partial file), a set of outputs all or none, reports left alone when unchanged,
// and no output may be one of the inputs. Every command writes through these.
#pragma once

#include "core/result.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace stereoshift {

// Writes through a temporary file renamed into place: a failure never leaves a partial output.
Status writeAtomically(const std::filesystem::path& path, const std::string& bytes);
// The same, unless the file already holds `bytes` (then it is left alone, its timestamp kept).
Status writeUnlessHolding(const std::filesystem::path& path, const std::string& bytes);

// One output waiting to be written ("-": standard output).
struct PendingOutput {
  std::string path;
  std::string bytes;
};
// Writes every output or none: each file's temporary first, then, only when all of them were
// written, the renames (the standard-output ones last). Returns the number of errors.
int writeAllOrNothing(const std::vector<PendingOutput>& outputs, std::ostream& log);
// Why nothing can be written at `path` (a directory there, a file where one of its folders must go),
// for checking a report or depfile path before any output of the run is written; "" when nothing
// blocks it (and for "-" and "").
std::string outputBlockedBecause(const std::string& path);

// Writes the report as JSON to `path` ('-': standard output; empty: nowhere).
bool writeReport(const std::string& path, const nlohmann::json& report);
// The same for a report already in text form ("-": standard output); an identical file is not rewritten.
bool writeReportText(const std::string& path, const std::string& text);

// "stereoshift: error: output 'x' is the input 'y'" when an output path names one of the inputs
// (the same file: device and inode, however it is spelt: ./x, an absolute path, a symbolic or a
// hard link). Only existing regular files can be the same file.
std::optional<std::string> outputThatIsAnInput(const std::vector<std::string>& outputs,
                                               const std::vector<std::string>& inputs);

}  // namespace stereoshift
