#include "cli/verify_command.h"

#include "transpiler/verify/stereo_verify.h"

#include <iostream>

namespace stereoshift {

int runVerifyCommand(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                     const VerifyCommandOptions& verify) {
  Diagnostics diags;
  std::vector<harness::StageModules> stages;
  std::string classification;
  if (!harness::buildStageModules(sources, options, &stages, &classification, diags)) {
    std::cerr << diags.format();
    int errors = std::max(1, diags.errorCount());
    std::cerr << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
    return 1;
  }
  const std::string name = sources.back().path;
  // Instanced mode rewrites 2D vertex shaders too (they draw once per eye): their instance reads and
  // eye routes are checked, with x left as it is.
  const bool rewrittenWithoutShift =
      options.eye.select == EyeSelect::InstanceIndex && classification == "2d-constant-w";
  if (classification != "perspective" && !rewrittenWithoutShift) {
    if (verify.json)
      std::cout << nlohmann::json{{"file", name}, {"classification", classification}, {"ok", true}, {"verified", false}}.dump(2)
                << "\n";
    else
      std::cout << name << ": " << classification << ": nothing is injected, nothing to verify\n";
    return 0;
  }
  std::string error;
  auto context = harness::VulkanContext::create(&error);
  if (!context) {
    std::cerr << name << ": error: no Vulkan device to run on (install mesa-vulkan-drivers): " << error << "\n";
    return 1;
  }
  harness::VerifySettings settings;
  settings.separation = verify.separation;
  settings.convergence = verify.convergence;
  settings.cutoff = options.cutoff != CutoffMode::None;
  settings.cutoffEpsilon = options.cutoff == CutoffMode::Exact ? 0.0f : options.cutoffEpsilon;
  // The bound of the arithmetic that was injected: 1 ULP for the compensated form, else the
  // analytic 2.5 ULP of three separately rounded fp32 operations (test/harness/stereo_verify.h).
  if (options.compensatedShift) settings.maxUlps = 1.0;
  settings.eyeSignName = options.eye.eyeSignName;
  settings.separationName = options.eye.separationName;
  settings.convergenceName = options.eye.convergenceName;
  settings.eyeSource = options.eye.select;
  settings.swapEyes = options.eye.swapEyes;
  settings.eyeRoute = options.eye.route;
  settings.eyeVaryingName = options.eye.eyeVaryingName;
  settings.eyeVaryingLocation = options.eye.eyeVaryingLocation;
  settings.shifted = !rewrittenWithoutShift;
  harness::VerifyResult r = harness::verifyStereo(*context, stages, settings);
  if (!r.error.empty()) {
    // The shader could not run: one line saying why, on stderr and (with --json) in the report.
    if (verify.json)
      std::cout << nlohmann::json{{"file", name}, {"classification", classification}, {"ok", false}, {"ran", false},
                                  {"error", r.error}}.dump(2)
                << "\n";
    std::cerr << name << ": error: " << r.error << "\n1 error generated.\n";
    return 1;
  }
  if (verify.json) {
    nlohmann::json j = r.json();
    j["file"] = name;
    j["classification"] = classification;
    j["shifted"] = settings.shifted;
    j["device"] = context->deviceName();
    j["bound_ulps"] = settings.maxUlps;
    j["ran"] = true;
    std::cout << j.dump(2) << "\n";
  } else if (r.mode == EyeSelect::Parameter) {
    std::cout << name << " on " << context->deviceName() << ": " << r.vertices << " vertices\n"
              << "  mono identity (eyeSign 0):   " << (r.monoIdentical ? "bit-exact" : "DIFFERS") << "\n"
              << "  other outputs per eye:       " << (r.otherOutputsUnchanged ? "unchanged" : "CHANGED") << "\n"
              << "  stereo x error:              " << r.maxStereoUlps << " ULP (bound " << settings.maxUlps << ": " << r.boundBasis
              << ")\n"
              << "  vertices kept by the cutoff: " << r.cutoffVertices << "\n";
  } else {
    // Single-pass: the eye comes from the view or the instance, so there is no eyeSign = 0 run.
    const bool multiview = r.mode == EyeSelect::ViewIndex;
    const std::string eye0 = options.eye.swapEyes ? "right" : "left", eye1 = options.eye.swapEyes ? "left" : "right";
    auto line = [](const std::string& label) { return "  " + label + std::string(label.size() < 29 ? 29 - label.size() : 1, ' '); };
    std::cout << name << " on " << context->deviceName() << ": " << r.vertices << " vertices, "
              << (multiview ? "multiview" : "instanced") << " single-pass stereo\n";
    if (multiview)
      std::cout << line("ran:") << "view 0 (" << eye0 << " eye) and view 1 (" << eye1
                << " eye), each against the reference of its eye\n";
    else
      std::cout << line("ran:") << 2 * r.instances << " instances for the original's " << r.instances
                << ": instance 2k+e against original instance k, eye e (0 " << eye0 << ", 1 " << eye1 << ")\n";
    std::cout << line("mono identity:") << "not run (no eyeSign 0 in this mode)\n"
              << line("eyeSign parameter:")
              << (!r.eyeSignDeclared ? "not declared" : r.eyeSignIgnored ? "ignored (a junk value changes no output)" : "READ")
              << "\n";
    if (!multiview)
      std::cout << line(std::string("eye in ") + (options.eye.route == EyeRoute::Layer ? "gl_Layer:" : "gl_ViewportIndex:"))
                << (r.eyeRouted ? "equals e" : "WRONG") << "\n"
                << line("eye in " + options.eye.eyeVaryingName + ":") << (r.eyeVaryingWritten ? "equals e" : "WRONG")
                << " (location " << options.eye.eyeVaryingLocation << ")\n";
    std::cout << line(multiview ? "other outputs per view:" : "other outputs per instance:")
              << (r.otherOutputsUnchanged ? "unchanged" : "CHANGED") << "\n"
              << line("stereo x error:") << r.maxStereoUlps << " ULP (bound " << settings.maxUlps << ": " << r.boundBasis << ")"
              << (settings.shifted ? "" : ", against x unshifted (" + classification + ": no shift)") << "\n"
              << line("vertices kept by the cutoff:") << r.cutoffVertices << "\n";
  }
  if (!verify.json) {
    for (const auto& s : r.synthesizedStages) std::cout << "  run behind:                  " << s << "\n";
    if (r.pushConstantsAsBuffer)
      std::cout << "  push constants:              over the device limit, bound as a uniform buffer\n";
    for (const auto& p : r.problems) std::cout << "  problem: " << p << "\n";
    std::cout << (r.ok ? "verified" : "FAILED") << "\n";
  }
  return r.ok ? 0 : 1;
}

}  // namespace stereoshift
