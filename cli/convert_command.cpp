// The single-shader and --pipeline command (see convert_command.h): convert() is the conversion
// itself, run inside the forked child; runConvertCommand the parent's side around it.
#include "cli/convert_command.h"

#include "cli/conversion_child.h"
#include "cli/diagnostic_output.h"
#include "cli/unified_diff.h"
#include "transpiler/source/file_io.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace stereoshift {

// -w drops the warnings; -Werror turns them into errors, and a stage with one is not written.
static void applyWarningOptions(const CliOptions& o, TranspileResult& r) {
  if (!o.noWarnings && o.warningsAs != "error") return;
  Diagnostics kept;
  bool promoted = false;
  for (Diagnostic d : r.diagnostics.all()) {
    if (d.severity == Severity::Warning) {
      if (o.noWarnings) continue;
      d.severity = Severity::Error;
      d.message += " [-Werror]";
      promoted = true;
    }
    kept.add(std::move(d));
  }
  r.diagnostics = std::move(kept);
  if (promoted) r.ok = false;
}

// Converts one list of stages (a single shader is a pipeline of one); the outputs are only
// collected: the caller writes all of them or, when a stage failed, none.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o, const std::function<std::string(size_t)>& outputFor,
            nlohmann::json& reports, std::ostream& log, std::vector<PendingOutput>* outputs) {
  std::vector<TranspileResult> results = sources.size() == 1 && !o.t.stage.has_value() && o.pipeline.empty()
                                             ? std::vector<TranspileResult>{transpile(sources[0], o.t)}
                                             : transpilePipeline(sources, o.t);
  int errors = 0;
  // A stage that failed without an error of its own failed with the pipeline (another stage's
  // error stopped it): counted once, not once more per stage.
  bool anyError = std::any_of(results.begin(), results.end(), [](const TranspileResult& r) { return r.diagnostics.hasErrors(); });
  for (auto& r : results) applyWarningOptions(o, r);
  for (size_t i = 0; i < results.size(); ++i) {
    auto& r = results[i];
    int diagnosticErrors = printDiagnostics(r.diagnostics, log);
    if (!r.passLog.empty()) log << r.passLog;
    if (!r.ok) {
      errors += diagnosticErrors > 0 ? diagnosticErrors : (anyError ? 0 : 1);
      r.report["ok"] = false;
      reports.push_back(r.report);
      continue;
    }
    std::string out = outputFor(i);
    if (out != "-" && !out.empty()) r.report["output_file"] = out;
    outputs->push_back({out, std::move(r.output)});
    r.report["ok"] = true;
    reports.push_back(r.report);
  }
  return errors;
}

namespace {

// --diff: each output against its input, on standard output; an output meant for standard output
// is then not printed as well. Binary outputs (SPIR-V) are named, as diff names them.
void printDiffs(const std::vector<std::string>& paths, std::vector<PendingOutput>& outputs) {
  for (size_t i = 0; i < outputs.size() && i < paths.size(); ++i) {
    std::string input;
    if (!readFile(paths[i], &input)) continue;
    std::string name = paths[i], converted = outputs[i].path.empty() || outputs[i].path == "-" ? paths[i] : outputs[i].path;
    // git's a/ and b/ prefixes for relative paths (`patch -p1` applies them), none for absolute ones.
    auto side = [](const char* prefix, const std::string& path) {
      return fs::path(path).is_absolute() ? path : prefix + path;
    };
    bool binary = input.find('\0') != std::string::npos || outputs[i].bytes.find('\0') != std::string::npos;
    if (binary && input != outputs[i].bytes)
      std::cout << "Binary files " << side("a/", name) << " and " << side("b/", converted) << " differ\n";
    else if (!binary)
      std::cout << unifiedDiff(input, outputs[i].bytes, side("a/", name), side("b/", converted));
  }
  // An output meant for standard output was shown as its diff.
  std::erase_if(outputs, [](const PendingOutput& out) { return out.path.empty() || out.path == "-"; });
  std::cout.flush();
}

}  // namespace

int runConvertCommand(const CliOptions& o, const std::vector<std::string>& paths) {
  auto outputFor = [&](size_t i) {
    if (paths.size() == 1) return o.output;
    if (o.output.empty() || o.output == "-") return std::string("-");
    return (fs::path(o.output) / fs::path(paths[i]).filename()).string();
  };
  std::vector<std::string> outputs;
  for (size_t i = 0; i < paths.size(); ++i) outputs.push_back(outputFor(i));
  const bool shaderOnStdout = std::any_of(outputs.begin(), outputs.end(), [](const std::string& out) {
    return out.empty() || out == "-";
  });
  // Two things on standard output cannot be told apart by whoever reads it.
  if (shaderOnStdout && o.reportPath == "-" && !o.diff) {
    std::cerr << "stereoshift: error: the converted shader and the report (--report -) would both go to standard "
                 "output: give -o FILE or --report FILE\n";
    printErrorSummary(1);
    return 2;
  }
  // Several stages' texts one after the other cannot be split again by whoever reads them.
  if (shaderOnStdout && paths.size() > 1 && !o.diff) {
    std::cerr << "stereoshift: error: the " << paths.size() << " stages of the pipeline would all go to standard output, "
              << "one after the other: give -o DIRECTORY (each output named as its input), or --diff\n";
    printErrorSummary(1);
    return 2;
  }
  // SPIR-V words on a terminal are no use to anyone and can upset it.
  if (shaderOnStdout && o.t.target == TargetLanguage::Spirv && !o.diff && ::isatty(STDOUT_FILENO)) {
    std::cerr << "stereoshift: error: binary SPIR-V would be written to the terminal: give -o FILE, redirect standard "
                 "output, or use --target spirv-asm\n";
    printErrorSummary(1);
    return 2;
  }
  if (!o.depfile.empty()) outputs.push_back(o.depfile);
  if (!o.reportPath.empty()) outputs.push_back(o.reportPath);
  if (auto clash = outputThatIsAnInput(outputs, paths)) {
    std::cerr << "stereoshift: error: " << *clash << "\n";
    printErrorSummary(1);
    return 1;
  }

  ConversionRun run;
  if (!runConversionChild(o, paths, outputFor, &run)) return 1;

  int errors = run.errors;
  // The report and the depfile are part of the set: a path that cannot take them stops the run
  // before any output is written.
  for (const std::string* extra : {&o.reportPath, &o.depfile})
    if (std::string why = outputBlockedBecause(*extra); !errors && !why.empty()) {
      std::cerr << *extra << ": error: cannot write the output: " << why << "; nothing was written\n";
      printErrorSummary(1);
      return 1;
    }
  if (!errors && o.diff) printDiffs(paths, run.outputs);
  if (!errors) errors += writeAllOrNothing(run.outputs, std::cerr);
  if (run.hasReport && !writeReport(o.reportPath, run.report)) ++errors;
  if (!errors && !run.depfileText.empty()) {
    if (Status written = writeAtomically(o.depfile, run.depfileText); !written) {
      std::cerr << located(written.error(), o.depfile).format() << "\n";
      ++errors;
    }
  }
  printErrorSummary(errors);
  return errors ? 1 : 0;
}

}  // namespace stereoshift
