// The conversion options of the command line (see conversion_options.h): registered on CLI11, then
// turned into TranspileOptions one group at a time, each bad value named with the values it may take.
#include "cli/conversion_options.h"

#include "passes/pass_registry.h"
#include "core/diagnostics.h"
#include "transpiler/source/identifiers.h"
#include "transpiler/source/stage_rules.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <set>
#include <tuple>
#include <sstream>

namespace stereoshift {

void addConversionOptions(CLI::App& app, CliOptions& o) {
  app.add_option("-S,--stage", o.stage, "Shader stage when the extension does not say: vert, tesc, tese, geom, frag, comp, mesh, task, rgen, rint, rahit, rchit, rmiss, rcall");
  app.add_option("-x,--language", o.language,
                 "Language of the input, whatever its file name says: glsl or hlsl (default: the name's .hlsl/.fx/.glsl "
                 "extension, else the content)");
  app.add_option("--stage-ext", o.stageExts,
                 "Read files ending in .EXT as STAGE shaders: --stage-ext EXT=STAGE (repeatable; e.g. vp=vert)")
      ->allow_extra_args(false);
  app.add_option("--target-env", o.targetEnv,
                 "SPIR-V environment, as glslc: vulkan1.0, vulkan1.1, vulkan1.2, vulkan1.3, opengl, opengl4.5 (default: the "
                 "source's: Vulkan 1.0 for Vulkan GLSL and HLSL, OpenGL for OpenGL GLSL; a Vulkan environment refuses "
                 "OpenGL GLSL, whose SPIR-V is OpenGL's)");
  app.add_option("--target-spv", o.targetSpv,
                 "SPIR-V version to make, as glslc: spv1.0 ... spv1.6 (default: the environment's; SPIR-V input keeps its own)");
  app.add_option("-e,--entry-point,--source-entrypoint", o.t.entryPoint,
                 "Entry point: HLSL (default: main, then VSMain/PSMain/GSMain/DSMain/HSMain/CSMain); GLSL: the function "
                 "compiled as main (default: main)");
  app.add_option("-D", o.t.defines, "Define a preprocessor macro: -DNAME or -DNAME=VALUE")->allow_extra_args(false);
  app.add_option("-I", o.t.includeDirs, "Add an #include search directory")->allow_extra_args(false);
  app.add_option("--target", o.target, "Output language: glsl, essl, hlsl, msl, spirv, spirv-asm (default: the input's own)");
  app.add_option("--target-version", o.targetVersion,
                 "Version of the output: GLSL 110-460, ESSL 100, 300, 310, 320, HLSL shader model 40, 41, 50, 51, 60-67 "
                 "(default: the input's own; HLSL 50)");
  app.add_option("--eye-source", o.eyeSource, "Where eyeSign/separation/convergence live: auto, uniform-block, push-constant, spec-constant, loose-uniforms; "
                 "3dmigoto (HLSL: 3Dmigoto's StereoParams texture at t125); "
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
  app.add_flag("--corrections-only", o.correctionsOnly,
               "Leave every clip position to the driver's own shift (3D Vision, geo-11) and write only the per-eye "
               "corrections (deferred unprojection in pixel shaders)");
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
  app.add_flag("--require-analysis", o.t.requireAnalysis,
               "Refuse a shader glslang cannot parse instead of splicing the shift from its text alone");
  app.add_flag("--unchecked-text-route", o.t.uncheckedTextRoute,
               "Where no Mesa is installed to compile a GLSL shader glslang refuses, take the text-only route "
               "anyway (said in the report) instead of refusing it");
  app.add_flag("--diff", o.diff,
               "Print the edits as a unified diff against the input (instead of the output text when it "
               "goes to standard output), to review them like a patch");
  app.add_flag("--force-reemit", o.t.forceReemit, "Re-emit shaders that need no change instead of copying them");
  app.add_option("--report", o.reportPath, "Write a JSON report of what was done ('-': standard output)");
  addMessageOptions(app, o.messages);
  groupConversionOptions(app);
}

void addMessageOptions(CLI::App& app, MessageOptions& o) {
  app.add_option("--color", o.colour,
                 "Colour the messages: auto (on a terminal, unless NO_COLOR is set), always, never (as clang's "
                 "-fdiagnostics-color)")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->capture_default_str()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)  // the last one said, as clang
      ->group("Messages");
  app.add_flag("--no-caret", o.noCaret,
               "Do not print the source line and a caret under the column after a located message "
               "(-fno-caret-diagnostics)")
      ->group("Messages");
  app.add_flag("-q,--quiet", o.quiet, "Print only warnings and errors: no progress bar, no summary line")
      ->group("Messages");
}

void groupConversionOptions(CLI::App& app) {
  // The help in sections, not one wall: each option under what it is about.
  static const std::map<std::string, const char*> groups = {
      {"stage", "Input"}, {"language", "Input"}, {"stage-ext", "Input"}, {"target-env", "Input"},
      {"target-spv", "Input"}, {"entry-point", "Input"}, {"D", "Input"}, {"I", "Input"},
      {"target", "Output"}, {"target-version", "Output"}, {"force-reemit", "Output"}, {"diff", "Output"},
      {"report", "Output"}, {"verify", "Output"}, {"output", "Output"}, {"pipeline", "Input"},
      {"depfile", "Output"}, {"w", "Output"}, {"W", "Output"}, {"timeout", "Output"},
      {"eye-source", "Eye parameters"}, {"multiview-params", "Eye parameters"}, {"swap-eyes", "Eye parameters"},
      {"eye-route", "Eye parameters"}, {"eye-varying-location", "Eye parameters"}, {"block-name", "Eye parameters"},
      {"instance-name", "Eye parameters"}, {"set", "Eye parameters"}, {"binding", "Eye parameters"},
      {"hlsl-register", "Eye parameters"}, {"gl-binding", "Eye parameters"}, {"spec-id-base", "Eye parameters"},
      {"cutoff-epsilon", "The shift"}, {"no-cutoff", "The shift"}, {"shift-form", "The shift"},
      {"fused-shift", "The shift"}, {"compensated-shift", "The shift"}, {"no-invariant", "The shift"},
      {"no-halo", "The shift"}, {"corrections-only", "The shift"},
      {"no-per-eye-view", "Per-eye fixes"}, {"per-eye-specular", "Per-eye fixes"}, {"camera-uniform", "Per-eye fixes"},
      {"no-deferred-unprojection", "Per-eye fixes"}, {"hud-at-depth", "Per-eye fixes"},
      {"pass", "Analysis and debugging"}, {"print-all", "Analysis and debugging"},
      {"validate-each", "Analysis and debugging"}, {"require-analysis", "Analysis and debugging"},
      {"unchecked-text-route", "Analysis and debugging"},
      {"service", "Conversion service"}, {"no-service", "Conversion service"}, {"service-idle", "Conversion service"},
      {"jobs", "Build"}, {"no-cache", "Build"}, {"job-timeout", "Build"}, {"job-memory", "Build"}, {"dry-run", "Build"}, {"files-from", "Build"},
      {"separation", "Verify"}, {"convergence", "Verify"}, {"json", "Verify"}};
  for (CLI::Option* option : app.get_options()) {
    std::string name = !option->get_lnames().empty() ? option->get_lnames().front()
                       : !option->get_snames().empty() ? option->get_snames().front()
                                                        : std::string();
    if (auto it = groups.find(name); it != groups.end()) option->group(it->second);
  }
}

namespace {

// The --pass names, from the pass registry (in pipeline order).
std::vector<std::string> registeredPassNames() {
  std::vector<std::string> names;
  for (const auto& pass : passRegistry()) names.emplace_back(pass.name);
  return names;
}

}  // namespace

const std::map<std::string, std::vector<std::string>>& enumeratedOptions() {
  static const std::map<std::string, std::vector<std::string>> options = {
      {"--stage", {"vert", "tesc", "tese", "geom", "frag", "comp", "mesh", "task"}},
      {"--target", {"glsl", "essl", "hlsl", "msl", "spirv", "spirv-asm"}},
      {"--eye-source", {"auto", "uniform-block", "push-constant", "spec-constant", "loose-uniforms", "multiview", "instanced", "3dmigoto"}},
      {"--multiview-params", {"auto", "uniform-block", "push-constant", "spec-constant", "loose-uniforms"}},
      {"--eye-route", {"layer", "viewport"}},
      {"--shift-form", {"branch", "select"}},
      {"--target-env", {"vulkan1.0", "vulkan1.1", "vulkan1.2", "vulkan1.3", "opengl", "opengl4.5"}},
      {"--target-spv", {"spv1.0", "spv1.1", "spv1.2", "spv1.3", "spv1.4", "spv1.5", "spv1.6"}},
      {"--pass", registeredPassNames()},
  };
  return options;
}

std::string validValues(const std::string& option) {
  std::string text;
  for (const auto& value : enumeratedOptions().at(option)) text += (text.empty() ? "(" : ", ") + value;
  return text + ")";
}

// Why `name` cannot name an injected declaration in GLSL and HLSL alike, or nothing when it can.
std::optional<std::string> notAnInjectableName(const std::string& name) {
  static const std::set<std::string> kReserved = {
      "main", "attribute", "const", "uniform", "varying", "buffer", "shared", "layout", "centroid", "flat",
      "smooth", "noperspective", "patch", "sample", "break", "continue", "do", "for", "while", "switch", "case",
      "default", "if", "else", "in", "out", "inout", "float", "double", "int", "void", "bool", "true", "false",
      "invariant", "precise", "discard", "return", "struct", "highp", "mediump", "lowp", "precision", "cbuffer",
      "tbuffer", "register", "static", "matrix", "vector", "packoffset", "technique", "pass", "typedef",
      "namespace", "class", "interface", "template", "this", "half", "uint", "dword", "string", "sampler",
      "texture", "row_major", "column_major", "nointerpolation", "groupshared", "volatile", "extern", "inline"};
  if (name.empty()) return std::string("is empty: it must be an identifier");
  if (!isIdentifierStart(name[0]) || !std::all_of(name.begin(), name.end(), isIdentifierChar))
    return std::string("is not an identifier (letters, digits and '_', not starting with a digit)");
  if (name.starts_with("gl_") || name.find("__") != std::string::npos)
    return std::string("is reserved (names starting with gl_ or holding __ belong to the language)");
  if (kReserved.count(name)) return std::string("is a keyword or the entry point");
  return std::nullopt;
}

namespace {

// --target-version must be a version of the output language (of any of the three source languages
// when the output is the input's own): 7 or 333 would reach the back end and fail there, or worse
// be written into the output.
std::optional<std::string> targetVersionProblem(TargetLanguage target, std::optional<int> version) {
  static const std::set<int> glsl = {110, 120, 130, 140, 150, 330, 400, 410, 420, 430, 440, 450, 460};
  static const std::set<int> essl = {100, 300, 310, 320};
  static const std::set<int> hlsl = {40, 41, 50, 51, 60, 61, 62, 63, 64, 65, 66, 67};
  if (!version) return std::nullopt;
  const int v = *version;
  const bool ok = target == TargetLanguage::Glsl   ? glsl.count(v) > 0
                  : target == TargetLanguage::Essl ? essl.count(v) > 0
                  : target == TargetLanguage::Hlsl ? hlsl.count(v) > 0
                  : target == TargetLanguage::Auto ? glsl.count(v) + essl.count(v) + hlsl.count(v) > 0
                                                   : true;  // MSL and SPIR-V versions are the back end's to check
  if (ok) return std::nullopt;
  return "--target-version " + std::to_string(v) + " is no version of the output language (GLSL 110-460, ESSL 100, " +
         "300, 310, 320, HLSL shader models 40, 41, 50, 51, 60-67)";
}

std::string unknownValue(const std::string& option, const std::string& value) {
  return "unknown " + option + " '" + value + "' " + validValues(option);
}

// The input side: the stage, the SPIR-V environment and version, --stage-ext, -x.
std::optional<std::string> finishInputOptions(CliOptions& o) {
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
  return std::nullopt;
}

std::optional<std::string> finishTargetOption(CliOptions& o) {
  static const std::map<std::string, TargetLanguage> targets = {
      {"glsl", TargetLanguage::Glsl}, {"essl", TargetLanguage::Essl}, {"hlsl", TargetLanguage::Hlsl},
      {"msl", TargetLanguage::Msl}, {"spirv", TargetLanguage::Spirv}, {"spirv-asm", TargetLanguage::SpirvAsm}};
  if (!o.target.empty()) {
    auto it = targets.find(o.target);
    if (it == targets.end()) return unknownValue("--target", o.target);
    o.t.target = it->second;
  }
  return std::nullopt;
}

// Where the eye parameters live, and the single-pass stereo modes.

std::optional<std::string> finishEyeOptions(CliOptions& o) {
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
  // 3Dmigoto's StereoParams texture (t125): transpile_options.h.
  if (o.eyeSource == "3dmigoto") paramsSource = "uniform-block";
  auto src = sources.find(paramsSource);
  if (src == sources.end()) return unknownValue("--eye-source", o.eyeSource);
  for (const auto& [option, name] : {std::pair{"--block-name", &o.t.eye.blockName}, std::pair{"--instance-name", &o.t.eye.instanceName}})
    if (auto why = notAnInjectableName(*name)) return std::string(option) + " '" + escapeControlBytes(*name) + "' " + *why;
  o.t.eye.source = src->second;
  o.t.eyeFrom3DMigoto = false;
  if (o.eyeSource == "3dmigoto") readEyeParamsFrom3DMigoto(o.t);
  return std::nullopt;
}

// The shift, the passes and where the injected block goes.
std::optional<std::string> finishShiftOptions(CliOptions& o) {
  if (o.shiftForm == "branch") o.t.shiftForm = ShiftForm::Branch;
  else if (o.shiftForm == "select") o.t.shiftForm = ShiftForm::Select;
  else return unknownValue("--shift-form", o.shiftForm);
  if (o.t.cutoffEpsilon < 0) return "--cutoff-epsilon must be >= 0";
  if (o.noCutoff) o.t.cutoff = CutoffMode::None;
  else if (o.t.cutoffEpsilon == 0.0f) o.t.cutoff = CutoffMode::Exact;
  o.t.invariantPosition = !o.noInvariant;
  o.t.haloFix = !o.noHalo;
  o.t.correctionsOnly = o.correctionsOnly;
  o.t.perEyeView = !o.noPerEyeView;
  o.t.deferredUnprojection = !o.noDeferredUnprojection;
  // Layout numbers are written into the emitted text, which glslang re-compiles before anything is
  // written; past the widths of its layout fields (a set below 63, a binding below 65535, a
  // specialization-constant id below 2047, a location below 4095) that re-compile fails, and past
  // 2^31 - 1 the number even reads as negative. Refused here instead, as the option's error.
  for (const auto& [name, value, max] : {std::tuple{"--set", o.set, kMaxDescriptorSet},
                                         std::tuple{"--binding", o.binding, kMaxBinding},
                                         std::tuple{"--hlsl-register", o.hlslRegister, kMaxBinding},
                                         std::tuple{"--gl-binding", o.glBinding, kMaxBinding}})
    if (value)
      if (auto problem = layoutNumberOutOfRange(name, *value, max)) return problem;
  // Up to eight eye parameters take consecutive ids from the base.
  if (auto problem = layoutNumberOutOfRange("--spec-id-base", o.t.eye.specIdBase, kMaxSpecId - 7)) return problem;
  if (auto problem = layoutNumberOutOfRange("--eye-varying-location", o.t.eye.eyeVaryingLocation, kMaxLocation))
    return problem;
  o.t.eye.descriptorSet = o.set;
  o.t.eye.binding = o.binding;
  o.t.eye.hlslRegister = o.hlslRegister;
  o.t.eye.glBinding = o.glBinding;
  o.t.targetVersion = o.targetVersion;
  if (auto problem = targetVersionProblem(o.t.target, o.targetVersion)) return problem;
  for (const auto& p : o.t.onlyPasses)
    if (!findPass(p)) return unknownValue("--pass", p);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> finishOptions(CliOptions& o) {
  if (auto problem = finishInputOptions(o)) return problem;
  if (auto problem = finishTargetOption(o)) return problem;
  if (auto problem = finishEyeOptions(o)) return problem;
  return finishShiftOptions(o);
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

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
  if (t.requireAnalysis) description["requireAnalysis"] = true;
  if (t.uncheckedTextRoute) description["uncheckedTextRoute"] = true;  // only when given: default keys unchanged
  if (t.eyeFrom3DMigoto) description["eyeFrom3DMigoto"] = true;
  if (t.correctionsOnly) description["correctionsOnly"] = true;
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

std::vector<std::string> glslcSpellings(int argc, char** argv, bool* depfileBesideOutput) {
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (i > 0 && arg.starts_with("-fshader-stage=")) {
      args.insert(args.end(), {"-S", arg.substr(15)});
    } else if (i > 0 && arg.starts_with("-fentry-point=")) {
      args.insert(args.end(), {"-e", arg.substr(14)});
    } else if (i > 0 && arg == "-MF") {
      args.push_back("--depfile");
    } else if (i > 0 && arg == "-MD") {
      *depfileBesideOutput = true;
    } else if (i > 0 && (arg == "-fcolor-diagnostics" || arg == "-fdiagnostics-color")) {
      args.insert(args.end(), {"--color", "always"});
    } else if (i > 0 && arg == "-fno-color-diagnostics") {
      args.insert(args.end(), {"--color", "never"});
    } else if (i > 0 && arg.starts_with("-fdiagnostics-color=")) {
      args.insert(args.end(), {"--color", arg.substr(20)});
    } else if (i > 0 && arg == "-fno-caret-diagnostics") {
      args.push_back("--no-caret");
    } else if (i > 0 && arg == "-fcaret-diagnostics") {
      // the default
    } else if (i > 0 && arg == "-c") {
      // glslc's "compile only, no link": what every conversion is.
    } else {
      args.push_back(arg);
    }
  }
  return args;
}

}  // namespace stereoshift
