// The single-shader and --pipeline command (see convert_command.h): convert() is the conversion
// itself, run inside the forked child; runConvertCommand the parent's side around it.
#include "cli/convert_command.h"

#include "cli/conversion_child.h"
#include "cli/diagnostic_output.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace stereoshift {

// Converts one list of stages (a single shader is a pipeline of one); the outputs are only
// collected: the caller writes all of them or, when a stage failed, none.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o, const std::function<std::string(size_t)>& outputFor,
            nlohmann::json& reports, std::ostream& log, std::vector<PendingOutput>* outputs) {
  std::vector<TranspileResult> results = sources.size() == 1 && !o.t.stage.has_value() && o.pipeline.empty()
                                             ? std::vector<TranspileResult>{transpile(sources[0], o.t)}
                                             : transpilePipeline(sources, o.t);
  int errors = 0;
  for (size_t i = 0; i < results.size(); ++i) {
    auto& r = results[i];
    int diagnosticErrors = printDiagnostics(r.diagnostics, log);
    if (!r.passLog.empty()) log << r.passLog;
    if (!r.ok) {
      errors += std::max(1, diagnosticErrors);
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

int runConvertCommand(const CliOptions& o, const std::vector<std::string>& paths) {
  auto outputFor = [&](size_t i) {
    if (paths.size() == 1) return o.output;
    if (o.output.empty() || o.output == "-") return std::string("-");
    return (fs::path(o.output) / fs::path(paths[i]).filename()).string();
  };
  std::vector<std::string> outputs;
  for (size_t i = 0; i < paths.size(); ++i) outputs.push_back(outputFor(i));
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
  if (!errors) errors += writeAllOrNothing(run.outputs, std::cerr);
  if (run.hasReport) writeReport(o.reportPath, run.report);
  if (!errors && !run.depfileText.empty()) {
    std::string error;
    if (!writeAtomically(o.depfile, run.depfileText, &error)) {
      std::cerr << o.depfile << ": error: " << error << "\n";
      ++errors;
    }
  }
  printErrorSummary(errors);
  return errors ? 1 : 0;
}

}  // namespace stereoshift
