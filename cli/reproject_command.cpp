// See reproject_command.h. The options mirror the conversion's where they mean the same thing
// (--target, --eye-source, --block-name, --set, --binding, ...), so a reprojection pass reads the
// eye parameters the converted shaders of the same application read.
#include "cli/reproject_command.h"

#include "cli/cli_support.h"
#include "cli/conversion_options.h"

#include "cli/path_option.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace stereoshift {

CLI::App* addReprojectCommand(CLI::App& app, ReprojectCliOptions& o) {
  auto* r = app.add_subcommand(
      "reproject",
      "Generate the shaders of a full-screen pass that synthesizes the other eye (or both eyes from the centre "
      "view) from one rendered view's colour and depth (docs/reprojection.md)");
  r->add_option("-o,--output", o.outputDir, "Directory the shaders and reproject-report.json are written to")->required()
      ->check(nonEmptyPath());
  r->add_option("--target", o.targets,
                "Output language, repeatable: glsl, essl, hlsl, msl, spirv, spirv-asm (default: glsl essl hlsl msl spirv)")
      ->allow_extra_args(false);
  r->add_option("--target-version", o.targetVersion, "GLSL/ESSL version or HLSL shader model (50, 51, 60) of the output");
  r->add_option("--report", o.reportPath, "Where the JSON report goes (default: <output>/reproject-report.json; '-': standard output)");
  // The eye parameters, as the converted shaders declare them.
  r->add_option("--eye-source", o.eyeSource,
                "Where eyeSign/separation/convergence live: auto (= uniform-block), uniform-block, push-constant, "
                "spec-constant, loose-uniforms (OpenGL GLSL / ESSL targets)")
      ->capture_default_str();
  r->add_option("--block-name", o.blockName, "Name of the eye parameters' uniform block / cbuffer / push-constant block")
      ->capture_default_str();
  r->add_option("--instance-name", o.instanceName, "Instance name of that block")->capture_default_str();
  r->add_option("--set", o.set, "Descriptor set of the block and the two textures (default 0)");
  r->add_option("--binding", o.binding, "Binding of the eye block (default: one past the textures')");
  r->add_option("--hlsl-register", o.hlslRegister, "HLSL cbuffer register b<N> of the eye block (default: --binding's)");
  r->add_option("--spec-id-base", o.specIdBase,
                "SpecId of eyeSign with --eye-source=spec-constant; separation and convergence follow")
      ->capture_default_str();
  r->add_option("--colour-binding", o.colourBinding, "Binding of the source colour texture")->capture_default_str();
  r->add_option("--depth-binding", o.depthBinding, "Binding of the source depth texture")->capture_default_str();
  // The source view and its depth.
  r->add_option("--source-eye", o.sourceEye,
                "The view the colour and depth are rendered from: left, right (eyeSign then names the eye to "
                "synthesize), centre (mono view: run the pass once per eye, half the parallax each)")
      ->capture_default_str();
  r->add_option("--depth", o.depth,
                "What the depth texture holds: linear (eye depth w), zero-to-one (device depth, z_ndc in [0,1]: "
                "Vulkan, D3D, Metal), minus-one-to-one (OpenGL, z_ndc in [-1,1] stored as (z+1)/2)")
      ->capture_default_str();
  r->add_flag("--reversed-z", o.reversedZ, "The projection maps the near plane to the far end of the depth range");
  r->add_option("--near", o.nearPlane, "Eye depth of the near plane")->capture_default_str();
  r->add_option("--far", o.farPlane, "Eye depth of the far plane, or inf for an infinite far plane")->capture_default_str();
  r->add_option("--depth-coefficients", o.depthCoefficients,
                "A,B: the projection's depth row z_clip = A*z_eye + B (GL-style P[2][2], P[2][3], w_clip = -z_eye); "
                "replaces --near/--far");
  // The search.
  r->add_option("--samples", o.samples, "Linear-search samples per pixel (2-256)")->capture_default_str();
  r->add_option("--search-near", o.searchNear,
                "How far in front of the screen the search reaches, as a fraction of the largest parallax behind it")
      ->capture_default_str();
  r->add_option("--refine", o.refine, "Refinement of the search's bracket: none, bisection, secant")->capture_default_str();
  r->add_option("--refine-steps", o.refineSteps, "Refinement steps (0-16)")->capture_default_str();
  r->add_option("--colour", o.colour,
                "Colour of a hit: nearest (the texel at the solved position), interpolated (the bracket's two "
                "samples mixed, the seed article's rule)")
      ->capture_default_str();
  r->add_option("--fill", o.fill,
                "Disoccluded pixels: background (repeat the background texel at the occluder's edge), "
                "farther-sample (the search's farther sample)")
      ->capture_default_str();
  r->add_flag("--mask", o.mask, "Also write a disocclusion mask (1 = disoccluded) to colour output 1, for inpainting");
  addMessageOptions(*r, o.messages);
  return r;
}

namespace {

struct Problems {
  std::vector<std::string> list;
  void add(std::string message) { list.push_back(std::move(message)); }
};

template <class T>
std::optional<T> parseNumber(const std::string& text, const char* option, Problems& problems) {
  T value{};
  const char* end = text.data() + text.size();
  auto [at, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || at != end) {
    problems.add(std::string(option) + ": '" + text + "' is not a " +
                 (std::is_floating_point_v<T> ? "number" : "non-negative integer"));
    return std::nullopt;
  }
  return value;
}

template <class E>
std::optional<E> parseChoice(const std::string& text, const char* option, const std::map<std::string, E>& choices,
                             Problems& problems) {
  auto found = choices.find(text);
  if (found != choices.end()) return found->second;
  std::string known;
  for (const auto& [name, value] : choices) known += (known.empty() ? "" : ", ") + name;
  problems.add(std::string("unknown ") + option + " '" + text + "' (" + known + ")");
  return std::nullopt;
}

}  // namespace

namespace {

// The versions each text target writes the reprojection shaders at (found by fuzz_reproject_options:
// `--target-version 2` was accepted and no GLSL came out): GLSL from 130 (texelFetch, gl_VertexID),
// ESSL from 300, HLSL shader model 4.0 and up (SPIRV-Cross writes neither at SM 3). MSL and SPIR-V
// have no version of this kind and ignore it. Checked for every target asked for (the default set
// includes GLSL, ESSL and HLSL alike).
void checkTargetVersion(int version, const std::vector<TargetLanguage>& languages, Problems& problems) {
  static const std::set<int> glsl = {130, 140, 150, 330, 400, 410, 420, 430, 440, 450, 460};
  static const std::set<int> essl = {300, 310, 320};
  static const std::set<int> hlsl = {40, 41, 50, 51, 60, 61, 62, 63, 64, 65, 66, 67};
  auto check = [&](TargetLanguage target, const char* name, const std::set<int>& versions, const char* valid) {
    if (std::find(languages.begin(), languages.end(), target) != languages.end() && !versions.count(version))
      problems.add("--target-version " + std::to_string(version) + " is no " + name + " version the reprojection "
                   "shaders can be written at (" + valid + "); with several targets, name the one it is for with --target");
  };
  check(TargetLanguage::Glsl, "GLSL", glsl, "130-460");
  check(TargetLanguage::Essl, "ESSL", essl, "300, 310, 320");
  check(TargetLanguage::Hlsl, "HLSL shader-model", hlsl, "40, 41, 50, 51, 60-67");
}

// --target (repeatable; the default set without one) and --target-version.
std::vector<TargetLanguage> parseTargets(const ReprojectCliOptions& c, ReprojectOptions& base, Problems& problems) {
  static const std::map<std::string, TargetLanguage> targets = {
      {"glsl", TargetLanguage::Glsl}, {"essl", TargetLanguage::Essl}, {"hlsl", TargetLanguage::Hlsl},
      {"msl", TargetLanguage::Msl}, {"spirv", TargetLanguage::Spirv}, {"spirv-asm", TargetLanguage::SpirvAsm}};
  std::vector<TargetLanguage> languages;
  for (const auto& t : c.targets)
    if (auto lang = parseChoice(t, "--target", targets, problems)) languages.push_back(*lang);
  if (c.targets.empty())
    languages = {TargetLanguage::Glsl, TargetLanguage::Essl, TargetLanguage::Hlsl, TargetLanguage::Msl, TargetLanguage::Spirv};
  if (!c.targetVersion.empty()) base.targetVersion = parseNumber<int>(c.targetVersion, "--target-version", problems);
  if (base.targetVersion) checkTargetVersion(*base.targetVersion, languages, problems);
  return languages;
}

// The eye parameters, as the converted shaders declare them, and the two textures' bindings.
void parseEyeOptions(const ReprojectCliOptions& c, ReprojectOptions& base, Problems& problems) {
  if (auto s = parseChoice(c.eyeSource, "--eye-source",
                           std::map<std::string, EyeSource>{{"auto", EyeSource::Auto},
                                                            {"uniform-block", EyeSource::UniformBlock},
                                                            {"push-constant", EyeSource::PushConstant},
                                                            {"spec-constant", EyeSource::SpecConstant},
                                                            {"loose-uniforms", EyeSource::LooseUniforms}},
                           problems))
    base.eye.source = *s;
  base.eye.blockName = c.blockName;
  base.eye.instanceName = c.instanceName;
  // Written into the generated text: an identifier the languages allow, or an option error (found
  // by fuzz_reproject_options: `--block-name '+2'` made shaders that did not compile).
  for (const auto& [option, name] : {std::pair{"--block-name", &c.blockName}, std::pair{"--instance-name", &c.instanceName}})
    if (auto why = notAnInjectableName(*name)) problems.add(std::string(option) + " '" + escapeControlBytes(*name) + "' " + *why);
  if (!c.set.empty()) base.eye.descriptorSet = parseNumber<uint32_t>(c.set, "--set", problems);
  if (!c.binding.empty()) base.eye.binding = parseNumber<uint32_t>(c.binding, "--binding", problems);
  if (!c.hlslRegister.empty()) base.eye.hlslRegister = parseNumber<uint32_t>(c.hlslRegister, "--hlsl-register", problems);
  if (auto v = parseNumber<uint32_t>(c.specIdBase, "--spec-id-base", problems)) base.eye.specIdBase = *v;
  if (auto v = parseNumber<uint32_t>(c.colourBinding, "--colour-binding", problems)) base.colourBinding = *v;
  if (auto v = parseNumber<uint32_t>(c.depthBinding, "--depth-binding", problems)) base.depthBinding = *v;
}

// The source view and what its depth texture holds.
void parseDepthOptions(const ReprojectCliOptions& c, ReprojectOptions& base, Problems& problems) {
  if (auto s = parseChoice(c.sourceEye, "--source-eye",
                           std::map<std::string, ReprojectSource>{{"left", ReprojectSource::LeftEye},
                                                                  {"right", ReprojectSource::RightEye},
                                                                  {"centre", ReprojectSource::Centre},
                                                                  {"center", ReprojectSource::Centre}},
                           problems))
    base.source = *s;
  if (auto d = parseChoice(c.depth, "--depth",
                           std::map<std::string, ReprojectDepth>{{"linear", ReprojectDepth::Linear},
                                                                 {"zero-to-one", ReprojectDepth::ZeroToOne},
                                                                 {"minus-one-to-one", ReprojectDepth::MinusOneToOne}},
                           problems))
    base.depth = *d;
  base.reversedZ = c.reversedZ;
  if (auto v = parseNumber<double>(c.nearPlane, "--near", problems)) base.nearPlane = *v;
  if (c.farPlane != "inf")
    if (auto v = parseNumber<double>(c.farPlane, "--far", problems)) base.farPlane = *v;
  if (!c.depthCoefficients.empty()) {
    auto parts = splitCommas(c.depthCoefficients);
    if (parts.size() != 2) {
      problems.add("--depth-coefficients: expected A,B (two numbers), got '" + c.depthCoefficients + "'");
    } else {
      base.depthScale = parseNumber<double>(parts[0], "--depth-coefficients", problems);
      base.depthOffset = parseNumber<double>(parts[1], "--depth-coefficients", problems);
    }
  }
}

// The search, the colour of a hit and the disocclusion fill.
void parseSearchOptions(const ReprojectCliOptions& c, ReprojectOptions& base, Problems& problems) {
  if (auto v = parseNumber<int>(c.samples, "--samples", problems)) base.samples = *v;
  if (auto v = parseNumber<double>(c.searchNear, "--search-near", problems)) base.searchNear = *v;
  if (auto r = parseChoice(c.refine, "--refine",
                           std::map<std::string, ReprojectRefinement>{{"none", ReprojectRefinement::None},
                                                                      {"bisection", ReprojectRefinement::Bisection},
                                                                      {"secant", ReprojectRefinement::Secant}},
                           problems))
    base.refinement = *r;
  if (auto v = parseNumber<int>(c.refineSteps, "--refine-steps", problems)) base.refinementSteps = *v;
  if (auto v = parseChoice(c.colour, "--colour",
                           std::map<std::string, ReprojectColour>{{"nearest", ReprojectColour::Nearest},
                                                                  {"interpolated", ReprojectColour::Interpolated}},
                           problems))
    base.colour = *v;
  if (auto v = parseChoice(c.fill, "--fill",
                           std::map<std::string, DisocclusionFill>{{"background", DisocclusionFill::Background},
                                                                   {"farther-sample", DisocclusionFill::FartherSample}},
                           problems))
    base.fill = *v;
  base.maskOutput = c.mask;
}

// The shaders of every target and the report, generated, then written all or none. Returns the
// exit status.
int generateAndWrite(const ReprojectCliOptions& c, const ReprojectOptions& base,
                     const std::vector<TargetLanguage>& languages) {
  nlohmann::json report;
  report["tool"] = std::string("stereoshift ") + version();
  report["options"] = describeReprojectOptions(base);
  std::vector<PendingOutput> outputs;
  int errors = 0;
  for (TargetLanguage lang : languages) {
    ReprojectOptions o = base;
    o.target = lang;
    ReprojectResult r = generateReprojectShaders(o);
    errors += printDiagnostics(r.diagnostics, std::cerr);
    if (!r.ok) {
      errors = std::max(errors, 1);
      continue;
    }
    for (auto& entry : r.report["outputs"]) report["outputs"].push_back(entry);
    for (auto& shader : r.shaders) outputs.push_back({(fs::path(c.outputDir) / shader.fileName).string(), shader.output});
  }
  if (errors) {
    std::cerr << "stereoshift: error: nothing was written\n";
    printErrorSummary(errors);
    return 1;
  }
  // Only now: a failed generation leaves no directory behind either.
  std::error_code ec;
  const bool created = !fs::exists(c.outputDir, ec);
  fs::create_directories(c.outputDir, ec);
  if (ec) {
    std::cerr << c.outputDir << ": error: cannot create the output directory: " << ec.message() << "\n";
    printErrorSummary(1);
    return 1;
  }
  std::string reportPath = c.reportPath.empty() ? (fs::path(c.outputDir) / "reproject-report.json").string() : c.reportPath;
  outputs.push_back({reportPath, report.dump(2) + "\n"});
  if (int failed = writeAllOrNothing(outputs, std::cerr)) {
    if (created) fs::remove(c.outputDir, ec);  // only when still empty: a failed run leaves nothing
    printErrorSummary(failed);
    return 1;
  }
  return 0;
}

}  // namespace

ParsedReproject parseReprojectOptions(const ReprojectCliOptions& c) {
  Problems problems;
  ParsedReproject parsed;
  parsed.targets = parseTargets(c, parsed.base, problems);
  parseEyeOptions(c, parsed.base, problems);
  parseDepthOptions(c, parsed.base, problems);
  parseSearchOptions(c, parsed.base, problems);
  for (TargetLanguage lang : parsed.targets) {
    ReprojectOptions o = parsed.base;
    o.target = lang;
    auto found = checkReprojectOptions(o);
    for (auto& p : found) problems.add(p);
    if (!found.empty()) break;  // the same problems again for every other target
  }
  parsed.problems = std::move(problems.list);
  return parsed;
}

int runReprojectCommand(const ReprojectCliOptions& c) {
  ParsedReproject parsed = parseReprojectOptions(c);
  if (!parsed.problems.empty()) {
    for (const auto& p : parsed.problems) std::cerr << "stereoshift: error: " << p << "\n";
    printErrorSummary(static_cast<int>(parsed.problems.size()));
    return 2;  // a usage error, as an unknown flag is
  }
  return generateAndWrite(c, parsed.base, parsed.targets);
}

}  // namespace stereoshift
