#include "cli/cli_support.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {


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


void addConversionOptions(CLI::App& app, CliOptions& o) {
  app.add_option("-S,--stage", o.stage, "Shader stage when the extension does not say: vert, tesc, tese, geom, frag, comp, mesh, task");
  app.add_option("-x,--language", o.language,
                 "Language of the input, whatever its file name says: glsl or hlsl (default: the name's .hlsl/.fx/.glsl "
                 "extension, else the content)");
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
  if (o.language == "glsl") o.t.language = SourceLanguage::Glsl;
  else if (o.language == "hlsl") o.t.language = SourceLanguage::Hlsl;
  else if (!o.language.empty()) return "unknown -x '" + o.language + "' (glsl, hlsl)";
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
  return writeReportText(path, report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

bool writeReportText(const std::string& path, const std::string& text) {
  if (path.empty()) return true;
  if (path == "-") {
    std::cout << text;
    return true;
  }
  // An identical report is left alone (a repeated no-op build rewrites nothing).
  std::string existing, error;
  if (readFile(path, &existing) && existing == text) return true;
  if (!writeAtomically(path, text, &error)) {
    std::cerr << "stereoshift: error: " << error << "\n";
    return false;
  }
  return true;
}

// Converts one list of stages (a single shader is a pipeline of one) and writes the outputs.
// `outputFor(i)` names each stage's output. Returns the number of errors.
int convert(const std::vector<SourceFile>& sources, const CliOptions& o,
            const std::function<std::string(size_t, const TranspileResult&)>& outputFor, nlohmann::json& reports,
            std::ostream& log) {
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

}  // namespace stereoshift

namespace stereoshift {

nlohmann::json describeOptions(const TranspileOptions& t) {
  auto opt = [](const auto& v) -> nlohmann::json { return v ? nlohmann::json(*v) : nlohmann::json(); };
  const EyeParamOptions& e = t.eye;
  nlohmann::json description = {
      {"stage", t.stage ? stageName(*t.stage) : ""},
      {"entryPoint", t.entryPoint},
      {"defines", t.defines},
      {"includeDirs", t.includeDirs},
      {"eye",
       {{"source", static_cast<int>(e.source)}, {"blockName", e.blockName}, {"instanceName", e.instanceName},
        {"names", {e.eyeSignName, e.separationName, e.convergenceName, e.hudDepthName, e.eyeOffsetXName,
                   e.eyeOffsetYName, e.eyeOffsetZName}},
        {"set", opt(e.descriptorSet)}, {"binding", opt(e.binding)}, {"hlslRegister", opt(e.hlslRegister)},
        {"glBinding", opt(e.glBinding)}, {"specIdBase", e.specIdBase}}},
      {"cutoff", static_cast<int>(t.cutoff)},
      {"cutoffEpsilon", t.cutoffEpsilon},
      {"shiftForm", static_cast<int>(t.shiftForm)},
      {"invariantPosition", t.invariantPosition},
      {"fusedShift", t.fusedShift},
      {"compensatedShift", t.compensatedShift},
      {"haloFix", t.haloFix},
      {"shiftThisStage", t.shiftThisStage},
      {"perEyeView", t.perEyeView},
      {"perEyeSpecular", t.perEyeSpecular},
      {"cameraUniform", t.cameraUniform},
      {"deferredUnprojection", t.deferredUnprojection},
      {"hudAtDepth", t.hudAtDepth},
      {"onlyPasses", t.onlyPasses},
      {"validateEach", t.validateEach},
      {"printAll", t.printAll},
      {"target", static_cast<int>(t.target)},
      {"targetVersion", opt(t.targetVersion)},
      {"verify", t.verify},
      {"forceReemit", t.forceReemit},
  };
  // Only when given, so the cache keys of builds without -x stay what they were.
  if (t.language) description["language"] = static_cast<int>(*t.language);
  return description;
}

}  // namespace stereoshift
