#include "cli/cli_support.h"

#include "cli/worker_pool.h"
#include "passes/pass_registry.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/stage_rules.h"

#include <CLI/CLI.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace stereoshift {


namespace {

// Where an output's bytes go: a symbolic link is followed (the link stays a link); a device or pipe
// (/dev/null, /dev/stdout) is written in place: renaming over it would replace it with a regular file.
struct OutputTarget {
  fs::path path;
  bool inPlace = false;
};

OutputTarget targetOf(const fs::path& requested) {
  std::error_code ec;
  OutputTarget target{requested, false};
  if (fs::is_symlink(target.path, ec)) target.path = fs::weakly_canonical(target.path, ec);
  target.inPlace = fs::exists(target.path, ec) && !fs::is_regular_file(target.path, ec);
  return target;
}

bool writeInPlace(const fs::path& path, const std::string& bytes, std::string* error) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) {
    *error = "cannot write '" + path.string() + "'";
    return false;
  }
  return true;
}

// The first half of an atomic write: the bytes in a temporary file beside `path`.
bool writeTemporary(const fs::path& path, const std::string& bytes, fs::path* temp, std::string* error) {
  std::error_code ec;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  *temp = path;
  *temp += ".stereoshift-tmp-" + std::to_string(::getpid());
  std::ofstream out(*temp, std::ios::binary | std::ios::trunc);
  if (!out) {
    *error = "cannot write '" + temp->string() + "'";
    return false;
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) {
    *error = "cannot write '" + temp->string() + "'";
    out.close();
    fs::remove(*temp, ec);
    return false;
  }
  return true;
}

// The second half: the temporary renamed into place (removed when that fails).
bool renameIntoPlace(const fs::path& temp, const fs::path& path, std::string* error) {
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    *error = "cannot rename '" + temp.string() + "' to '" + path.string() + "': " + ec.message();
    fs::remove(temp, ec);
    return false;
  }
  return true;
}

}  // namespace

// Writes through a temporary file renamed into place: a failure never leaves a partial output.
bool writeAtomically(const fs::path& requested, const std::string& bytes, std::string* error) {
  OutputTarget target = targetOf(requested);
  if (target.inPlace) return writeInPlace(target.path, bytes, error);
  fs::path temp;
  return writeTemporary(target.path, bytes, &temp, error) && renameIntoPlace(temp, target.path, error);
}

int writeAllOrNothing(const std::vector<PendingOutput>& outputs, std::ostream& log) {
  struct Staged {
    const PendingOutput* output;
    OutputTarget target;
    fs::path temp;
  };
  std::vector<Staged> staged;
  std::error_code ec;
  for (const auto& output : outputs) {
    if (output.path == "-" || output.path.empty()) continue;
    Staged s{&output, targetOf(output.path), {}};
    std::string error;
    if (!s.target.inPlace && !writeTemporary(s.target.path, output.bytes, &s.temp, &error)) {
      log << output.path << ": error: " << error << "\n";
      for (const auto& done : staged)
        if (!done.temp.empty()) fs::remove(done.temp, ec);
      return 1;
    }
    staged.push_back(std::move(s));
  }
  int errors = 0;
  for (const auto& s : staged) {
    std::string error;
    bool written = s.target.inPlace ? writeInPlace(s.target.path, s.output->bytes, &error)
                                    : renameIntoPlace(s.temp, s.target.path, &error);
    if (!written) {
      log << s.output->path << ": error: " << error << "\n";
      ++errors;
    }
  }
  for (const auto& output : outputs)
    if (output.path == "-" || output.path.empty()) std::cout << output.bytes;
  return errors;
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
  const char* hangOn = std::getenv("STEREOSHIFT_TEST_HANG");
  for (const auto& p : paths) {
    if (hangOn && *hangOn && fs::path(p).filename() == hangOn)
      while (true) ::pause();  // test-only (see the header): a conversion that never finishes
    SourceFile s{p, {}};
    std::error_code ec;
    if (p == "-") {
      // Standard input, as glslc reads it: the stage and language then come from -S / -x or the
      // text, and diagnostics name it <stdin>.
      s.path = kStdinName;
      std::ostringstream text;
      text << std::cin.rdbuf();
      s.contents = text.str();
    } else if (fs::is_directory(p, ec) || !readFile(p, &s.contents)) {
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
  app.add_option("-S,--stage", o.stage, "Shader stage when the extension does not say: vert, tesc, tese, geom, frag, comp, mesh, task, rgen, rint, rahit, rchit, rmiss, rcall");
  app.add_option("-x,--language", o.language,
                 "Language of the input, whatever its file name says: glsl or hlsl (default: the name's .hlsl/.fx/.glsl "
                 "extension, else the content)");
  app.add_option("--stage-ext", o.stageExts,
                 "Read files ending in .EXT as STAGE shaders: --stage-ext EXT=STAGE (repeatable; e.g. vp=vert)")
      ->allow_extra_args(false);
  app.add_option("--target-env", o.targetEnv,
                 "SPIR-V environment, as glslc: vulkan1.0 (default), vulkan1.1, vulkan1.2, vulkan1.3, opengl, opengl4.5");
  app.add_option("--target-spv", o.targetSpv,
                 "SPIR-V version to make, as glslc: spv1.0 ... spv1.6 (default: the environment's; SPIR-V input keeps its own)");
  app.add_option("-e,--entry-point", o.t.entryPoint, "HLSL entry point (default: main, then VSMain/PSMain/GSMain/DSMain/HSMain/CSMain)");
  app.add_option("-D", o.t.defines, "Define a preprocessor macro: -DNAME or -DNAME=VALUE")->allow_extra_args(false);
  app.add_option("-I", o.t.includeDirs, "Add an #include search directory")->allow_extra_args(false);
  app.add_option("--target", o.target, "Output language: glsl, essl, hlsl, msl, spirv, spirv-asm (default: the input's own)");
  app.add_option("--target-version", o.targetVersion, "GLSL/ESSL version or HLSL shader model (50, 51, 60) of the output");
  app.add_option("--eye-source", o.eyeSource, "Where eyeSign/separation/convergence live: auto, uniform-block, push-constant, spec-constant, loose-uniforms; "
                 "or single-pass stereo, eyeSign from the view index (multiview) or the instance index (instanced)");
  app.add_option("--multiview-params", o.singlePassParams,
                 "With --eye-source multiview|instanced: where separation/convergence live (auto, uniform-block, "
                 "push-constant, spec-constant, loose-uniforms)")->capture_default_str();
  app.add_flag("--swap-eyes", o.t.eye.swapEyes, "Single-pass stereo: view 0 / even instances are the right eye");
  app.add_option("--eye-route", o.eyeRoute, "--eye-source instanced: the eye goes to the render-target layer or the viewport index (layer, viewport)")
      ->capture_default_str();
  app.add_option("--eye-varying-location", o.t.eye.eyeVaryingLocation,
                 "--eye-source instanced: location of the eye varyings (`stereoEye` into the fragment stage, `stereoEyeStage` / `stereoEyePatch` between earlier stages)")
      ->capture_default_str();
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
  app.add_option("--pass", o.t.onlyPasses, passHelpText())->allow_extra_args(false);
  app.add_flag("--print-all", o.t.printAll, "Print the SPIR-V after every pass to stderr");
  app.add_flag("--validate-each", o.t.validateEach, "Validate the SPIR-V after every pass");
  app.add_flag("--verify", o.t.verify, "Recompile every emitted GLSL/HLSL output with glslang");
  app.add_flag("--force-reemit", o.t.forceReemit, "Re-emit shaders that need no change instead of copying them");
  app.add_option("--report", o.reportPath, "Write a JSON report of what was done ('-': standard output)");
}

namespace {

// The --pass names, from the pass registry (in pipeline order).
std::vector<std::string> registeredPassNames() {
  std::vector<std::string> names;
  for (const auto& pass : passRegistry()) names.emplace_back(pass.name);
  return names;
}

// The options whose values come from a fixed set, and the set: for the messages about a bad or a
// missing value.
const std::map<std::string, std::vector<std::string>>& enumeratedOptions() {
  static const std::map<std::string, std::vector<std::string>> options = {
      {"--stage", {"vert", "tesc", "tese", "geom", "frag", "comp", "mesh", "task"}},
      {"--target", {"glsl", "essl", "hlsl", "msl", "spirv", "spirv-asm"}},
      {"--eye-source", {"auto", "uniform-block", "push-constant", "spec-constant", "loose-uniforms", "multiview", "instanced"}},
      {"--multiview-params", {"auto", "uniform-block", "push-constant", "spec-constant", "loose-uniforms"}},
      {"--eye-route", {"layer", "viewport"}},
      {"--shift-form", {"branch", "select"}},
      {"--target-env", {"vulkan1.0", "vulkan1.1", "vulkan1.2", "vulkan1.3", "opengl", "opengl4.5"}},
      {"--target-spv", {"spv1.0", "spv1.1", "spv1.2", "spv1.3", "spv1.4", "spv1.5", "spv1.6"}},
      {"--pass", registeredPassNames()},
  };
  return options;
}

// "(a, b, c)": the valid values of an enumerated option.
std::string validValues(const std::string& option) {
  std::string text;
  for (const auto& value : enumeratedOptions().at(option)) text += (text.empty() ? "(" : ", ") + value;
  return text + ")";
}

std::string unknownValue(const std::string& option, const std::string& value) {
  return "unknown " + option + " '" + value + "' " + validValues(option);
}

}  // namespace

std::optional<std::string> finishOptions(CliOptions& o) {
  if (!o.stage.empty()) {
    o.t.stage = stageFromName(o.stage);
    if (!o.t.stage) return "unknown stage '" + o.stage + "' " + validValues("--stage");
  }
  if (!o.targetEnv.empty()) {
    o.t.targetEnv = targetEnvFromName(o.targetEnv);
    if (!o.t.targetEnv) return unknownValue("--target-env", o.targetEnv);
  }
  if (!o.targetSpv.empty()) {
    const auto& known = enumeratedOptions().at("--target-spv");
    auto it = std::find(known.begin(), known.end(), o.targetSpv);
    if (it == known.end()) return unknownValue("--target-spv", o.targetSpv);
    o.t.targetSpv = static_cast<int>(it - known.begin());
    if (o.t.targetEnv == TargetEnv::OpenGL45 && *o.t.targetSpv > 0)
      return "--target-spv " + o.targetSpv + " with --target-env " + o.targetEnv + ": OpenGL takes SPIR-V 1.0 only";
  }
  for (const auto& mapping : o.stageExts) {
    size_t equals = mapping.find('=');
    std::string extension = mapping.substr(0, equals);
    while (!extension.empty() && extension.front() == '.') extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::optional<Stage> stage = equals == std::string::npos ? std::nullopt : stageFromName(mapping.substr(equals + 1));
    if (extension.empty() || extension.find_first_of("./") != std::string::npos || !stage)
      return "--stage-ext '" + mapping + "': expected EXT=STAGE with STAGE one of " + validValues("--stage") +
             ", e.g. --stage-ext vp=vert";
    o.t.stageExtensions[extension] = *stage;
  }
  if (o.language == "glsl") o.t.language = SourceLanguage::Glsl;
  else if (o.language == "hlsl") o.t.language = SourceLanguage::Hlsl;
  else if (!o.language.empty()) return "unknown -x '" + o.language + "' (glsl, hlsl)";
  static const std::map<std::string, TargetLanguage> targets = {
      {"glsl", TargetLanguage::Glsl}, {"essl", TargetLanguage::Essl}, {"hlsl", TargetLanguage::Hlsl},
      {"msl", TargetLanguage::Msl}, {"spirv", TargetLanguage::Spirv}, {"spirv-asm", TargetLanguage::SpirvAsm}};
  if (!o.target.empty()) {
    auto it = targets.find(o.target);
    if (it == targets.end()) return unknownValue("--target", o.target);
    o.t.target = it->second;
  }
  static const std::map<std::string, EyeSource> sources = {
      {"auto", EyeSource::Auto}, {"uniform-block", EyeSource::UniformBlock},
      {"push-constant", EyeSource::PushConstant}, {"spec-constant", EyeSource::SpecConstant},
      {"loose-uniforms", EyeSource::LooseUniforms}};
  // Single-pass stereo: eyeSign from the view or instance; the other parameters where --multiview-params says.
  std::string paramsSource = o.eyeSource;
  o.t.eye.select = EyeSelect::Parameter;
  if (o.eyeSource == "multiview" || o.eyeSource == "instanced") {
    o.t.eye.select = o.eyeSource == "multiview" ? EyeSelect::ViewIndex : EyeSelect::InstanceIndex;
    paramsSource = o.singlePassParams;
    if (!sources.count(paramsSource)) return unknownValue("--multiview-params", paramsSource);
  }
  if (o.eyeRoute == "layer") o.t.eye.route = EyeRoute::Layer;
  else if (o.eyeRoute == "viewport") o.t.eye.route = EyeRoute::Viewport;
  else return unknownValue("--eye-route", o.eyeRoute);
  auto src = sources.find(paramsSource);
  if (src == sources.end()) return unknownValue("--eye-source", o.eyeSource);
  o.t.eye.source = src->second;
  if (o.shiftForm == "branch") o.t.shiftForm = ShiftForm::Branch;
  else if (o.shiftForm == "select") o.t.shiftForm = ShiftForm::Select;
  else return unknownValue("--shift-form", o.shiftForm);
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
  for (const auto& p : o.t.onlyPasses)
    if (!findPass(p)) return unknownValue("--pass", p);
  return std::nullopt;
}

size_t editDistance(const std::string& a, const std::string& b) {
  // Optimal string alignment: the Levenshtein table plus a swap of two neighbours ("sorce" is one
  // edit from "source", "souce" from "source", "suorce" one swap).
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

namespace {

// The command's apps: the top-level one and the subcommand being parsed (whose options count too).
std::vector<const CLI::App*> appsInUse(const CLI::App& app) {
  std::vector<const CLI::App*> apps{&app};
  for (const CLI::App* sub : app.get_subcommands()) apps.push_back(sub);
  return apps;
}

const CLI::Option* findOption(const std::vector<const CLI::App*>& apps, const std::string& name) {
  for (const CLI::App* a : apps)
    if (const CLI::Option* option = a->get_option_no_throw(name)) return option;
  return nullptr;
}

// "--eye-source" for an option that has a long name, "-D" for one that has only a short one.
std::string longestName(const CLI::Option& option) {
  if (!option.get_lnames().empty()) return "--" + option.get_lnames().front();
  if (!option.get_snames().empty()) return "-" + option.get_snames().front();
  return option.get_name();
}

// The known option nearest to `given` (an unknown "--name" or "--name=value"), when it is close
// enough to be a typo: at most a third of the name's letters wrong.
std::optional<std::string> nearestOption(const std::vector<const CLI::App*>& apps, std::string given) {
  given = given.substr(0, given.find('='));
  if (given.rfind("--", 0) != 0) return std::nullopt;
  std::string name = given.substr(2);
  std::optional<std::string> best;
  size_t bestDistance = std::max<size_t>(1, name.size() / 3) + 1;
  for (const CLI::App* a : apps)
    for (const CLI::Option* option : a->get_options())
      for (const auto& candidate : option->get_lnames()) {
        size_t distance = editDistance(name, candidate);
        if (distance < bestDistance) {
          bestDistance = distance;
          best = "--" + candidate;
        }
      }
  return best;
}

// CLI11's type names, in words.
std::string expectedValue(const CLI::Option& option) {
  std::string type = option.get_type_name();
  if (type == "UINT") return "a non-negative integer";
  if (type == "INT") return "an integer";
  if (type == "FLOAT") return "a number";
  return type.empty() ? "a value" : type;
}

std::vector<std::string> usageErrors(const CLI::App& app, const CLI::ParseError& error) {
  const std::vector<const CLI::App*> apps = appsInUse(app);
  const std::string what = error.what();
  std::vector<std::string> messages;
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    std::vector<std::string> extras;
    for (const CLI::App* a : apps)
      for (const auto& arg : a->remaining())
        if (std::find(extras.begin(), extras.end(), arg) == extras.end()) extras.push_back(arg);
    for (size_t i = 0; i < extras.size(); ++i) {
      const std::string& arg = extras[i];
      if (arg.size() < 2 || arg[0] != '-') {
        messages.push_back("unexpected argument '" + arg + "'");
        continue;
      }
      // "--job-timout 5": the word after an unknown option is taken to be its value, not another error.
      if (arg.find('=') == std::string::npos && i + 1 < extras.size() && extras[i + 1].rfind("-", 0) != 0) ++i;
      std::string message = "unknown option '" + arg + "'";
      if (auto nearest = nearestOption(apps, arg)) message += "; did you mean '" + *nearest + "'?";
      messages.push_back(message);
    }
    if (!messages.empty()) return messages;
  }
  // "Could not convert: --binding = -1": a value of the wrong type.
  static const std::string couldNotConvert = "Could not convert: ";
  if (dynamic_cast<const CLI::ConversionError*>(&error) && what.rfind(couldNotConvert, 0) == 0) {
    std::string rest = what.substr(couldNotConvert.size());
    size_t equals = rest.find(" = ");
    if (equals != std::string::npos) {
      std::string name = rest.substr(0, equals), value = rest.substr(equals + 3);
      if (const CLI::Option* option = findOption(apps, name))
        return {longestName(*option) + ": invalid value '" + value + "' (expected " + expectedValue(*option) + ")"};
    }
  }
  // "--target: 1 required TEXT missing": an option given without its value.
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    std::string given = what.substr(0, what.find(':'));
    if (const CLI::Option* option = findOption(apps, given)) {
      std::string name = longestName(*option);
      bool enumerated = enumeratedOptions().count(name) > 0;
      return {name + " needs a value " + (enumerated ? validValues(name) : "(" + expectedValue(*option) + ")")};
    }
  }
  return {what};
}

}  // namespace

int reportParseError(const CLI::App& app, const CLI::ParseError& error, std::ostream& log) {
  // --help and --version arrive as "errors" with exit code 0: CLI11 prints those itself.
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);
  std::vector<std::string> messages = usageErrors(app, error);
  for (const auto& message : messages) log << "stereoshift: error: " << message << "\n";
  printErrorSummary(static_cast<int>(messages.size()));
  return 2;
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

std::optional<std::string> outputThatIsAnInput(const std::vector<std::string>& outputs,
                                               const std::vector<std::string>& inputs) {
  struct stat in {}, out {};
  for (const auto& output : outputs) {
    if (output.empty() || output == "-") continue;
    // stat() follows links: a symbolic link to the input is the input. A device (-o /dev/stdout
    // with the input /dev/stdin on one terminal) is written in place, never replaced: not compared.
    if (::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) continue;
    for (const auto& input : inputs)
      if (::stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino)
        return "output '" + output + "' is the input '" + input + "'; it would be overwritten";
  }
  return std::nullopt;
}

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

namespace {

// What the conversion child hands back to the parent, which writes: the error count so far, the
// outputs (written only when there is no error), the report and the depfile text.
struct ConversionRun {
  int errors = 0;
  std::vector<PendingOutput> outputs;
  bool hasReport = false;
  nlohmann::json report;
  std::string depfileText;
};

// The report travels as JSON text; the outputs as raw bytes (SPIR-V is binary).
std::string serialize(const ConversionRun& run) {
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

bool deserialize(const std::string& wire, ConversionRun* run) {
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

// Runs in the conversion child: reads and converts, prints the diagnostics, writes nothing.
ConversionRun convertInChild(const CliOptions& o, const std::vector<std::string>& paths,
                             const std::function<std::string(size_t)>& outputFor) {
  ConversionRun run;
  std::vector<SourceFile> sources;
  run.errors = readSources(paths, &sources, std::cerr);
  if (run.errors) return run;
  nlohmann::json reports = nlohmann::json::array();
  run.errors = convert(sources, o, outputFor, reports, std::cerr, &run.outputs);
  if (!run.errors && !o.depfile.empty()) {
    std::vector<std::string> targets, dependencies;
    for (const auto& r : reports)
      if (r.contains("output_file")) targets.push_back(r["output_file"].get<std::string>());
    for (const auto& s : sources)
      if (s.path != kStdinName) dependencies.push_back(s.path);
    for (const auto& r : reports)
      for (const auto& inc : r.value("included_files", nlohmann::json::array())) dependencies.push_back(inc.get<std::string>());
    if (targets.empty()) {
      std::cerr << "stereoshift: error: --depfile needs an output file (-o)\n";
      ++run.errors;
    } else {
      run.depfileText = makeDepfile(targets, dependencies);
    }
  }
  if (run.errors) {
    // A failed pipeline writes nothing, so no stage's report names an output file.
    run.outputs.clear();
    run.depfileText.clear();
    for (auto& r : reports) r.erase("output_file");
  }
  run.hasReport = true;
  run.report = sources.size() == 1 && !reports.empty() ? reports[0] : reports;
  return run;
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
  if (!o.depfile.empty()) outputs.push_back(o.depfile);
  if (!o.reportPath.empty()) outputs.push_back(o.reportPath);
  if (auto clash = outputThatIsAnInput(outputs, paths)) {
    std::cerr << "stereoshift: error: " << *clash << "\n";
    printErrorSummary(1);
    return 1;
  }

  ConversionRun run;
  // The conversion runs in a forked child: a crash in the front end (glslang overflows its stack
  // on some inputs) or a conversion past the time limit becomes a clear error instead of a core
  // dump or a hang. STEREOSHIFT_NO_FORK=1 keeps it in process, for a debugger (no time limit then).
  if (const char* noFork = std::getenv("STEREOSHIFT_NO_FORK"); noFork && *noFork && std::string(noFork) != "0") {
    run = convertInChild(o, paths, outputFor);
  } else {
    TaskOutcome outcome = runIsolatedOnce(
        [&] {
          std::string wire = serialize(convertInChild(o, paths, outputFor));
          std::cout.flush();
          std::cerr.flush();
          std::fflush(nullptr);
          return wire;
        },
        o.timeoutSeconds);
    if (!outcome.completed) {
      // runIsolated's words for a task it stopped at the limit start with "timed out".
      if (outcome.failure.rfind("timed out", 0) == 0) {
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g", o.timeoutSeconds);
        std::cerr << (paths.front() == "-" ? std::string(kStdinName) : paths.front()) << ": error: conversion exceeded the " << limit
                  << " s time limit (--timeout); no output was written\n";
      } else {
        std::cerr << (paths.front() == "-" ? std::string(kStdinName) : paths.front()) << ": error: stereoshift " << outcome.failure
                  << " while converting this shader; no output was written\n";
      }
      printErrorSummary(1);
      return 1;
    }
    if (!deserialize(outcome.payload, &run)) {
      std::cerr << (paths.front() == "-" ? std::string(kStdinName) : paths.front()) << ": error: stereoshift's conversion process answered garbage; no output was written\n";
      printErrorSummary(1);
      return 1;
    }
  }

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
                   e.eyeOffsetYName, e.eyeOffsetZName, e.projScaleXName}},
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
  if (t.targetEnv) description["targetEnv"] = targetEnvName(*t.targetEnv);
  if (t.targetSpv) description["targetSpv"] = *t.targetSpv;
  for (const auto& [extension, stage] : t.stageExtensions) description["stageExtensions"][extension] = stageName(stage);
  // Single-pass stereo only where asked for, so the default fingerprints (cache keys) stay as they were.
  if (e.select != EyeSelect::Parameter)
    description["eye"]["singlePass"] = {{"select", static_cast<int>(e.select)}, {"swapEyes", e.swapEyes},
                                        {"route", static_cast<int>(e.route)}, {"varying", e.eyeVaryingName},
                                        {"location", e.eyeVaryingLocation}};
  return description;
}

}  // namespace stereoshift
