// stereoshift: a thin command line over the library (transpiler/stereoshift.h).
//
//   stereoshift [options] <input> -o <output>          one shader
//   stereoshift [options] --pipeline a.vert,a.geom,a.frag -o <dir>   one pipeline
//   stereoshift build <src-dir> -o <out-dir> [options] a whole tree (pipelines by base name)
#include "cli/verify_command.h"
#include "transpiler/front_end.h"
#include "transpiler/stereoshift.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using namespace stereoshift;

namespace {

// Writes through a temporary file renamed into place: a failure never leaves a partial output.
bool writeAtomically(const fs::path& requested, const std::string& bytes, std::string* error) {
  std::error_code ec;
  fs::path path = requested;
  // A symlink is followed (the link stays a link); a device or pipe (/dev/null, /dev/stdout) is
  // written in place: renaming over it would replace it with a regular file.
  if (fs::is_symlink(path, ec)) path = fs::weakly_canonical(path, ec);
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) {
      *error = "cannot write '" + path.string() + "'";
      return false;
    }
    return true;
  }
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  fs::path temp = path;
  temp += ".stereoshift-tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) {
      *error = "cannot write '" + temp.string() + "'";
      return false;
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) {
      *error = "cannot write '" + temp.string() + "'";
      fs::remove(temp, ec);
      return false;
    }
  }
  fs::rename(temp, path, ec);
  if (ec) {
    *error = "cannot rename '" + temp.string() + "' to '" + path.string() + "': " + ec.message();
    fs::remove(temp, ec);
    return false;
  }
  return true;
}

// Prints the diagnostics; returns how many were errors.
int printDiagnostics(const Diagnostics& diags, std::ostream& log) {
  log << diags.format();
  return diags.errorCount();
}

// Reads every path into `sources`; each one that cannot be read (or is a directory) is reported to
// `log`. Returns how many failed.
int readSources(const std::vector<std::string>& paths, std::vector<SourceFile>* sources, std::ostream& log) {
  int failed = 0;
  for (const auto& p : paths) {
    SourceFile s{p, {}};
    std::error_code ec;
    if (fs::is_directory(p, ec) || !readFile(p, &s.contents)) {
      log << p << ": error: cannot read file\n";
      ++failed;
      continue;
    }
    sources->push_back(std::move(s));
  }
  return failed;
}

void printErrorSummary(int errors) {
  if (errors > 0) std::cerr << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
}

struct CliOptions {
  TranspileOptions t;
  std::vector<std::string> inputs;
  std::string output;
  std::string stage, target, eyeSource = "auto", shiftForm = "branch";
  std::string pipeline;
  std::string reportPath;
  std::string depfile;  // single shader / pipeline: Makefile-style dependencies of the outputs
  bool noCutoff = false, exactCutoff = false, noInvariant = false, noHalo = false;
  bool noPerEyeView = false, noDeferredUnprojection = false;
  std::optional<uint32_t> set, binding, hlslRegister, glBinding;
  std::optional<int> targetVersion;
  int jobs = 0;  // build: worker threads (0: one per core)
};

void addConversionOptions(CLI::App& app, CliOptions& o) {
  app.add_option("-S,--stage", o.stage, "Shader stage when the extension does not say: vert, tesc, tese, geom, frag, comp, mesh, task");
  app.add_option("-e,--entry-point", o.t.entryPoint, "HLSL entry point (default: main, then VSMain/PSMain/GSMain/DSMain/HSMain/CSMain)");
  app.add_option("-D", o.t.defines, "Define a preprocessor macro: -DNAME or -DNAME=VALUE")->allow_extra_args(false);
  app.add_option("-I", o.t.includeDirs, "Add an #include search directory")->allow_extra_args(false);
  app.add_option("--target", o.target, "Output language: glsl, essl, hlsl, msl, spirv, spirv-asm (default: the input's own)");
  app.add_option("--target-version", o.targetVersion, "GLSL/ESSL version or HLSL shader model (50, 51, 60) of the output");
  app.add_option("--eye-source", o.eyeSource, "Where eyeSign/separation/convergence live: auto, uniform-block, push-constant, spec-constant, loose-uniforms");
  app.add_option("--block-name", o.t.eye.blockName, "Name of the injected uniform block / cbuffer")->capture_default_str();
  app.add_option("--instance-name", o.t.eye.instanceName, "Instance name of the injected block")->capture_default_str();
  app.add_option("--set", o.set, "Descriptor set of the injected block (default 0)");
  app.add_option("--binding", o.binding, "Binding of the injected block (default: one past the highest used)");
  app.add_option("--hlsl-register", o.hlslRegister, "HLSL cbuffer register b<N> of the injected block (default: one past the highest used)");
  app.add_option("--gl-binding", o.glBinding, "OpenGL uniform-block binding (default: none, bound by name)");
  app.add_option("--spec-id-base", o.t.eye.specIdBase, "SpecId of eyeSign with --eye-source=spec-constant; separation and convergence follow")->capture_default_str();
  app.add_option("--cutoff-epsilon", o.t.cutoffEpsilon, "Leave vertices with |w - 1| <= epsilon unshifted (0: the driver's exact w != 1)")->capture_default_str();
  app.add_flag("--no-cutoff", o.noCutoff, "Shift every vertex, including w == 1 (2D) ones");
  app.add_option("--shift-form", o.shiftForm, "How the cutoff is coded: branch (if) or select (branch-free)")->capture_default_str();
  app.add_flag("--fused-shift", o.t.fusedShift, "Compute the shift as one fma (GLSL >= 400, ESSL >= 320, HLSL, MSL, SPIR-V)");
  app.add_flag("--compensated-shift", o.t.compensatedShift,
               "Compute the shift with error-free transformations (about 30 instructions, <= 1 ULP); needs `precise`");
  app.add_flag("--no-invariant", o.noInvariant, "Do not mark the position invariant / the shift NoContraction");
  app.add_flag("--no-halo", o.noHalo, "Do not shift outputs derived from the clip position");
  app.add_flag("--no-per-eye-view", o.noPerEyeView,
               "Keep the mono camera position in view vectors that offset texture coordinates (relief mapping)");
  app.add_flag("--per-eye-specular", o.t.perEyeSpecular,
               "Also use the per-eye camera position where a view vector only feeds lighting");
  app.add_option("--camera-uniform", o.t.cameraUniform,
                 "The camera-position uniform (NAME or Block.member) when detection does not find it");
  app.add_flag("--no-deferred-unprojection", o.noDeferredUnprojection,
               "Leave `InvM * vec4(ndc, depth, 1)` position reconstruction (deferred lighting) mono");
  app.add_flag("--hud-at-depth", o.t.hudAtDepth,
               "Place shaders proven 2D (w = 1) at the eye depth given by the injected `hudDepth` uniform");
  app.add_option("--pass", o.t.onlyPasses,
                 "Run only this pass (repeatable): clip-position-detection, hud-at-depth, eye-params, halo, "
                 "stereo-shift, per-eye-view, deferred-unprojection")
      ->allow_extra_args(false);
  app.add_flag("--print-all", o.t.printAll, "Print the SPIR-V after every pass to stderr");
  app.add_flag("--validate-each", o.t.validateEach, "Validate the SPIR-V after every pass");
  app.add_flag("--verify", o.t.verify, "Recompile every emitted GLSL/HLSL output with glslang");
  app.add_flag("--force-reemit", o.t.forceReemit, "Re-emit shaders that need no change instead of copying them");
  app.add_option("--report", o.reportPath, "Write a JSON report of what was done ('-': standard output)");
}

std::optional<std::string> finishOptions(CliOptions& o) {
  if (!o.stage.empty()) {
    o.t.stage = stageFromName(o.stage);
    if (!o.t.stage) return "unknown stage '" + o.stage + "' (vert, tesc, tese, geom, frag, comp, mesh, task)";
  }
  static const std::map<std::string, TargetLanguage> targets = {
      {"glsl", TargetLanguage::Glsl}, {"essl", TargetLanguage::Essl}, {"hlsl", TargetLanguage::Hlsl},
      {"msl", TargetLanguage::Msl}, {"spirv", TargetLanguage::Spirv}, {"spirv-asm", TargetLanguage::SpirvAsm}};
  if (!o.target.empty()) {
    auto it = targets.find(o.target);
    if (it == targets.end()) return "unknown --target '" + o.target + "'";
    o.t.target = it->second;
  }
  static const std::map<std::string, EyeSource> sources = {
      {"auto", EyeSource::Auto}, {"uniform-block", EyeSource::UniformBlock},
      {"push-constant", EyeSource::PushConstant}, {"spec-constant", EyeSource::SpecConstant},
      {"loose-uniforms", EyeSource::LooseUniforms}};
  auto src = sources.find(o.eyeSource);
  if (src == sources.end()) return "unknown --eye-source '" + o.eyeSource + "'";
  o.t.eye.source = src->second;
  if (o.shiftForm == "branch") o.t.shiftForm = ShiftForm::Branch;
  else if (o.shiftForm == "select") o.t.shiftForm = ShiftForm::Select;
  else return "unknown --shift-form '" + o.shiftForm + "' (branch, select)";
  if (o.t.cutoffEpsilon < 0) return "--cutoff-epsilon must be >= 0";
  if (o.noCutoff) o.t.cutoff = CutoffMode::None;
  else if (o.t.cutoffEpsilon == 0.0f) o.t.cutoff = CutoffMode::Exact;
  o.t.invariantPosition = !o.noInvariant;
  o.t.haloFix = !o.noHalo;
  o.t.perEyeView = !o.noPerEyeView;
  o.t.deferredUnprojection = !o.noDeferredUnprojection;
  o.t.eye.descriptorSet = o.set;
  o.t.eye.binding = o.binding;
  o.t.eye.hlslRegister = o.hlslRegister;
  o.t.eye.glBinding = o.glBinding;
  o.t.targetVersion = o.targetVersion;
  static const std::vector<std::string> passNames = {"clip-position-detection", "hud-at-depth", "eye-params", "halo",
                                                     "stereo-shift", "per-eye-view", "deferred-unprojection"};
  for (const auto& p : o.t.onlyPasses)
    if (std::find(passNames.begin(), passNames.end(), p) == passNames.end()) return "unknown --pass '" + p + "'";
  return std::nullopt;
}

bool writeReport(const std::string& path, const nlohmann::json& report) {
  if (path.empty()) return true;
  if (path == "-") {
    std::cout << report.dump(2) << "\n";
    return true;
  }
  std::string error;
  if (!writeAtomically(path, report.dump(2) + "\n", &error)) {
    std::cerr << "stereoshift: error: " << error << "\n";
    return false;
  }
  return true;
}

// Converts one list of stages (a single shader is a pipeline of one) and writes the outputs.
// `outputFor(i)` names each stage's output. Returns the number of errors.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o,
            const std::function<std::string(size_t, const TranspileResult&)>& outputFor, nlohmann::json& reports,
            std::ostream& log = std::cerr) {
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
    std::string out = outputFor(i, r);
    if (out == "-" || out.empty()) {
      std::cout << r.output;
    } else {
      std::string error;
      if (!writeAtomically(out, r.output, &error)) {
        log << out << ": error: " << error << "\n";
        ++errors;
        continue;
      }
      r.report["output_file"] = out;
    }
    r.report["ok"] = true;
    reports.push_back(r.report);
  }
  return errors;
}

// Make/Ninja depfile text: `target...: dependency...`, spaces and '#' escaped with a backslash, '$'
// doubled (Ninja's and GNU make's shared rules).
std::string makeDepfile(const std::vector<std::string>& targets, std::vector<std::string> dependencies) {
  auto escape = [](const std::string& path) {
    std::string out;
    for (char c : path) {
      if (c == ' ' || c == '#') out += '\\';
      if (c == '$') out += '$';
      out += c;
    }
    return out;
  };
  std::sort(dependencies.begin(), dependencies.end());
  dependencies.erase(std::unique(dependencies.begin(), dependencies.end()), dependencies.end());
  std::string text;
  for (size_t i = 0; i < targets.size(); ++i) text += (i ? " " : "") + escape(targets[i]);
  text += ":";
  for (const auto& d : dependencies) text += " \\\n  " + escape(d);
  return text + "\n";
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

int runBuild(const std::string& sourceDir, const std::string& outDir, CliOptions& o) {
  std::error_code ec;
  if (!fs::is_directory(sourceDir, ec)) {
    std::cerr << sourceDir << ": error: not a directory\n";
    printErrorSummary(1);
    return 1;
  }
  // Shaders are the files whose name carries a stage; everything else (includes, docs) is skipped.
  std::map<std::string, std::vector<fs::path>> pipelines;
  std::vector<fs::path> files;
  // An output directory inside the source tree is not part of the source.
  fs::path outCanonical = fs::weakly_canonical(outDir, ec);
  for (auto it = fs::recursive_directory_iterator(sourceDir, ec); it != fs::recursive_directory_iterator(); ++it) {
    if (it->is_directory() && fs::weakly_canonical(it->path(), ec) == outCanonical) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files)
    if (stageFromPath(f.string())) pipelines[pipelineKey(f.string())].push_back(f);

  // Pipelines convert in parallel, in-process (glslang is initialised once); diagnostics and report
  // entries are kept per pipeline and emitted in path order, so the result does not depend on the
  // number of threads or on scheduling.
  std::vector<std::pair<std::string, std::vector<fs::path>>> jobs(pipelines.begin(), pipelines.end());
  std::vector<std::string> logs(jobs.size());
  std::vector<nlohmann::json> jobReports(jobs.size(), nlohmann::json::array());
  std::vector<int> jobErrors(jobs.size(), 0);
  std::atomic<size_t> next{0};
  std::atomic<int> done{0};
  std::mutex progress;
  int total = 0;
  for (const auto& [key, stages] : jobs) total += static_cast<int>(stages.size());
  bool tty = ::isatty(2);
  auto work = [&] {
    for (size_t i; (i = next++) < jobs.size();) {
      const auto& [key, stages] = jobs[i];
      std::ostringstream log;
      std::vector<SourceFile> sources;
      std::vector<std::string> paths;
      for (const auto& p : stages) paths.push_back(p.string());
      jobErrors[i] += readSources(paths, &sources, log);
      CliOptions stageOptions = o;
      stageOptions.pipeline = "group";
      // Each shader directory and an `include` directory beside it are include roots.
      for (const auto& s : sources) {
        fs::path dir = fs::path(s.path).parent_path();
        stageOptions.t.includeDirs.push_back(dir.string());
        std::error_code dirError;
        if (fs::is_directory(dir / "include", dirError)) stageOptions.t.includeDirs.push_back((dir / "include").string());
      }
      jobErrors[i] += convert(sources, stageOptions,
                              [&](size_t k, const TranspileResult&) {
                                return (fs::path(outDir) / fs::relative(sources[k].path, sourceDir)).string();
                              },
                              jobReports[i], log);
      logs[i] = log.str();
      int finished = done += static_cast<int>(stages.size());
      if (tty) {
        std::lock_guard<std::mutex> lock(progress);
        std::cerr << "\r[" << finished << "/" << total << "] " << key << "\x1b[K" << std::flush;
      }
    }
  };
  unsigned threads = o.jobs > 0 ? static_cast<unsigned>(o.jobs) : std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, std::max<size_t>(1, jobs.size()));
  ensureGlslangInitialized();
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (tty) std::cerr << "\n";

  nlohmann::json reports = nlohmann::json::array();
  int errors = 0;
  for (size_t i = 0; i < jobs.size(); ++i) {
    std::cerr << logs[i];
    for (auto& r : jobReports[i]) reports.push_back(std::move(r));
    errors += jobErrors[i];
  }
  nlohmann::json summary;
  summary["tool"] = std::string("stereoshift ") + version();
  summary["shaders"] = reports;
  std::map<std::string, int> counts;
  for (const auto& r : reports) counts[r.value("classification", r.value("ok", false) ? "?" : "failed")]++;
  summary["classification_counts"] = counts;
  std::string reportPath = o.reportPath.empty() ? (fs::path(outDir) / "stereoshift-report.json").string() : o.reportPath;
  writeReport(reportPath, summary);
  std::cerr << "converted " << reports.size() << " shaders from " << sourceDir << " into " << outDir;
  for (const auto& [c, n] : counts) std::cerr << ", " << n << " " << c;
  std::cerr << "\n";
  printErrorSummary(errors);
  return errors ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"stereoshift: converts mono shaders (GLSL, ESSL, HLSL, SPIR-V) into stereoscopic ones"};
  app.set_version_flag("--version", std::string("stereoshift ") + version());
  CliOptions o;
  addConversionOptions(app, o);
  app.add_option("input", o.inputs, "Input shader (.vert .tesc .tese .geom .frag .comp .mesh .task, .hlsl, .spv)");
  app.add_option("-o,--output", o.output, "Output file (a directory with --pipeline); '-' or none: standard output");
  app.add_option("--pipeline", o.pipeline, "Comma-separated stages of one pipeline; only its last pre-rasterization stage is shifted");
  app.add_option("--depfile", o.depfile,
                 "Write the outputs' dependencies (the inputs and every #included file) as a Makefile-style depfile");

  CliOptions b;
  auto* build = app.add_subcommand("build", "Convert a whole shader tree: stages grouped into pipelines by base name");
  addConversionOptions(*build, b);
  std::string buildSource, buildOut;
  build->add_option("source", buildSource, "Source directory")->required();
  build->add_option("-o,--output", buildOut, "Output directory (mirrors the source tree)")->required();
  build->add_option("-j,--jobs", b.jobs, "Worker threads (default: one per core); the output does not depend on it");

  CliOptions v;
  VerifyCommandOptions verifyOptions;
  auto* verify = app.add_subcommand(
      "verify", "Run the original and the stereo shader on the CPU Vulkan driver (lavapipe) and check the shift");
  addConversionOptions(*verify, v);
  verify->add_option("input", v.inputs, "Shader, or the stages of one pipeline (only pre-rasterization stages run)");
  verify->add_option("--separation", verifyOptions.separation, "Separation used for the check")->capture_default_str();
  verify->add_option("--convergence", verifyOptions.convergence, "Convergence used for the check")->capture_default_str();
  verify->add_flag("--json", verifyOptions.json, "Machine-readable result");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  if (*verify) {
    if (auto error = finishOptions(v)) {
      std::cerr << "stereoshift: error: " << *error << "\n";
      printErrorSummary(1);
      return 2;
    }
    std::vector<SourceFile> sources;
    if (int failed = readSources(v.inputs, &sources, std::cerr)) {
      printErrorSummary(failed);
      return 1;
    }
    if (sources.empty()) {
      std::cerr << "stereoshift: error: no input file (see verify --help)\n";
      printErrorSummary(1);
      return 2;
    }
    return runVerifyCommand(sources, v.t, verifyOptions);
  }

  if (*build) {
    if (auto error = finishOptions(b)) {
      std::cerr << "stereoshift: error: " << *error << "\n";
      printErrorSummary(1);
      return 2;
    }
    return runBuild(buildSource, buildOut, b);
  }

  if (auto error = finishOptions(o)) {
    std::cerr << "stereoshift: error: " << *error << "\n";
    printErrorSummary(1);
    return 2;
  }
  std::vector<std::string> paths = o.pipeline.empty() ? o.inputs : splitCommas(o.pipeline);
  if (!o.pipeline.empty()) paths.insert(paths.end(), o.inputs.begin(), o.inputs.end());
  if (paths.empty()) {
    std::cerr << "stereoshift: error: no input file (see --help)\n";
    return 2;
  }
  if (paths.size() > 1 && o.pipeline.empty()) {
    std::cerr << "stereoshift: error: several inputs need --pipeline (or use 'stereoshift build')\n";
    return 2;
  }
  std::vector<SourceFile> sources;
  int readErrors = readSources(paths, &sources, std::cerr);
  if (readErrors) {
    printErrorSummary(readErrors);
    return 1;
  }
  nlohmann::json reports = nlohmann::json::array();
  int errors = convert(sources, o,
                       [&](size_t i, const TranspileResult&) {
                         if (sources.size() == 1) return o.output;
                         if (o.output.empty() || o.output == "-") return std::string("-");
                         return (fs::path(o.output) / fs::path(sources[i].path).filename()).string();
                       },
                       reports);
  writeReport(o.reportPath, sources.size() == 1 && !reports.empty() ? reports[0] : reports);
  if (!errors && !o.depfile.empty()) {
    std::vector<std::string> targets, dependencies;
    for (const auto& r : reports)
      if (r.contains("output_file")) targets.push_back(r["output_file"].get<std::string>());
    for (const auto& s : sources) dependencies.push_back(s.path);
    for (const auto& r : reports)
      for (const auto& inc : r.value("included_files", nlohmann::json::array())) dependencies.push_back(inc.get<std::string>());
    std::string error;
    if (targets.empty()) {
      std::cerr << "stereoshift: error: --depfile needs an output file (-o)\n";
      ++errors;
    } else if (!writeAtomically(o.depfile, makeDepfile(targets, dependencies), &error)) {
      std::cerr << o.depfile << ": error: " << error << "\n";
      ++errors;
    }
  }
  printErrorSummary(errors);
  return errors ? 1 : 0;
}
