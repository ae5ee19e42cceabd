#include "cli/verify_command.h"

#include "cli/diagnostic_output.h"
#include "cli/worker_pool.h"
#include "transpiler/d3dasm/asm_route.h"
#include "transpiler/d3dasm/asm_verify.h"
#include "transpiler/verify/stereo_verify.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace stereoshift {

namespace {

// The verified shader or pipeline as its messages name it: every stage, in the order given.
std::string joinedPaths(const std::vector<SourceFile>& sources) {
  std::string names;
  for (const auto& source : sources) names += (names.empty() ? "" : ", ") + source.path;
  return names;
}

// D3D shader assembly does not run on Vulkan: it is converted by the same route `stereoshift`
// takes (the assembly route, d3dasm/asm_route.h) and both texts are run on the assembly interpreter instead.
int runAssemblyVerify(const SourceFile& input, const TranspileOptions& options, const VerifyCommandOptions& verify) {
  const std::string& name = input.path;
  TranspileResult converted = transpile(input, options);
  if (!converted.ok) {
    printErrorSummary(std::max(1, printDiagnostics(converted.diagnostics, std::cerr)));
    return 1;
  }
  const std::string model = converted.record.assembly ? converted.record.assembly->shaderModel : "";
  if (converted.copiedThrough) {
    const std::string why = converted.record.assembly ? converted.record.assembly->unchangedBecause : "";
    if (verify.json)
      std::cout << nlohmann::json{{"file", name}, {"language", "d3d-asm"}, {"shader_model", model}, {"ok", true},
                                  {"verified", false}, {"copied_because", why}}.dump(2)
                << "\n";
    else
      std::cout << name << ": " << model << ": copied unchanged (" << why << "), nothing to verify\n";
    return 0;
  }
  if (converted.record.assembly && !converted.record.assembly->corrections.empty()) {
    // A pixel shader's corrections: not what verify runs (the shift of a position); saying
    // "verified" after no run would be a yes to nothing.
    const std::string why = "its " + std::to_string(converted.record.assembly->corrections.size()) +
                            " pixel-shader correction(s) are not run by verify, which checks the position shift of "
                            "vertex, domain and geometry shaders";
    if (verify.json)
      std::cout << nlohmann::json{{"file", name}, {"language", "d3d-asm"}, {"shader_model", model}, {"ok", false},
                                  {"ran", false}, {"verified", false}, {"error", why}}.dump(2)
                << "\n";
    std::cerr << name << ": error: nothing to verify: " << why << "\n1 error generated.\n";
    return 1;
  }
  d3dasm::AsmVerifyOptions settings;
  const ShiftSpec shift = assemblyShiftSpec(options);
  settings.cutoff = shift.cutoff;
  settings.cutoffEpsilon = shift.epsilon;
  if (converted.record.assembly) {
    settings.movedLanes = converted.record.assembly->movedLanes;
    settings.positionLeftToDriver = converted.record.assembly->positionLeftToDriver;
  }
  d3dasm::AsmVerifyResult r = d3dasm::verifyAssemblyConversion(input.contents, converted.output, settings);
  if (!r.ran) {
    if (verify.json)
      std::cout << nlohmann::json{{"file", name}, {"language", "d3d-asm"}, {"ok", false}, {"ran", false},
                                  {"error", r.error}}.dump(2)
                << "\n";
    std::cerr << name << ": error: the assembly interpreter cannot run " << r.error << "\n1 error generated.\n";
    return 1;
  }
  if (r.nothingToVerify) {  // no position output: no run was made, so nothing is verified
    std::cerr << name << ": error: nothing to verify: the shader writes no position\n1 error generated.\n";
    return 1;
  }
  if (verify.json) {
    std::cout << nlohmann::json{{"file", name}, {"language", "d3d-asm"}, {"shader_model", model}, {"ok", r.ok},
                                {"ran", true}, {"verified", true}, {"device", "assembly interpreter (CPU)"},
                                {"position", r.positionRegister}, {"samples", r.samples}, {"runaway_samples", r.runaway},
                                {"mono_runs", r.monoRuns}, {"mono_mismatches", r.monoMismatches},
                                {"stereo_runs", r.stereoRuns}, {"other_output_mismatches", r.otherOutputMismatches},
                                {"position_yzw_mismatches", r.positionYzwMismatches}, {"cutoff_runs", r.cutoffRuns},
                                {"cutoff_mismatches", r.cutoffMismatches}, {"shifted_runs", r.shiftedRuns},
                                {"shifted_failures", r.shiftedFailures}, {"samples_with_w_one", r.samplesWithWOne},
                                {"max_stereo_error", r.worstError}, {"bound_at_max", r.worstBound},
                                {"max_error_over_bound", r.worstRatio}, {"moved_lane_runs", r.movedLaneRuns},
                                {"moved_lane_failures", r.movedLaneFailures},
                                {"max_moved_lane_error_over_bound", r.worstMovedLaneRatio},
                                {"first_failure", r.firstFailure},
                                {"checked", {"separation 0: every output bit for bit the original's",
                                             "eye -1 and +1: x against x + s*(w - c) in double from the original's x "
                                             "and w, every other output unchanged but the lanes moved with x: a copy "
                                             "equal to the shifted x, another lane the original's plus its "
                                             "coefficient times the exact shift"}}}.dump(2)
              << "\n";
    return r.ok ? 0 : 1;
  }
  char error[160];
  std::snprintf(error, sizeof error, "%.3g (bound there %.3g: %.2f of it)", r.worstError, r.worstBound, r.worstRatio);
  std::cout << name << " (" << model << ") on the assembly interpreter: " << r.samples << " input sets, "
            << r.stereoRuns << " stereo runs\n"
            << "  eye parameters:                separation in (0, 0.1] per eye sign, convergence in [0.5, 5], "
               "drawn per input set\n"
            << "  mono identity (separation 0):  " << (r.monoMismatches ? "DIFFERS" : "bit-exact") << "\n"
            << "  other outputs per eye:         " << (r.otherOutputMismatches ? "CHANGED" : "unchanged") << "\n"
            << (settings.positionLeftToDriver ? "  position (left to the driver): " : "  position y, z, w per eye:      ")
            << (r.positionYzwMismatches ? "CHANGED" : "unchanged") << "\n"
            << (settings.positionLeftToDriver ? "  shifted x of its copies:       " : "  stereo x error:                ") << error << ", " << r.shiftedFailures << " of " << r.shiftedRuns
            << " runs over it\n"
            << "  vertices kept by the cutoff:   " << r.cutoffRuns << (r.cutoffMismatches ? " (x CHANGED)" : " (x bit-exact)")
            << "\n"
            << "  input sets with w = 1:         " << r.samplesWithWOne << " of " << r.samples << "\n";
  if (r.movedLaneRuns) {
    char moved[160];
    std::snprintf(moved, sizeof moved, "%.2f of the bound at worst, %d of %d over it", r.worstMovedLaneRatio,
                  r.movedLaneFailures, r.movedLaneRuns);
    std::cout << "  lanes moved with x:            " << moved << "\n";
  }
  if (r.runaway) std::cout << "  runaway input sets:            " << r.runaway << " (the instruction limit; left out)\n";
  if (!r.firstFailure.empty()) std::cout << "  problem: " << r.firstFailure << "\n";
  std::cout << (r.ok ? "verified" : "FAILED") << "\n";
  return r.ok ? 0 : 1;
}

int verifyInThisProcess(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                        const VerifyCommandOptions& verify) {
  for (const SourceFile& source : sources) {
    if (decideInputKind(source) != InputKind::D3DAssembly) continue;
    if (sources.size() == 1) return runAssemblyVerify(source, options, verify);
    std::cerr << source.path << ": error: D3D shader assembly is verified one file at a time\n1 error generated.\n";
    return 1;
  }
  Diagnostics diags;
  std::vector<harness::StageModules> stages;
  std::string classification;
  if (!harness::buildStageModules(sources, options, &stages, &classification, diags)) {
    std::cerr << diags.format();
    int errors = std::max(1, diags.errorCount());
    std::cerr << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
    return 1;
  }
  const std::string name = joinedPaths(sources);
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
  settings.cutoff = options.cutoff;
  settings.cutoffEpsilon = options.cutoffEpsilon;
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
    if (r.movedLaneComponents)
      std::cout << "  lanes moved with x:          " << r.maxMovedLaneUlps << " ULP (bound " << harness::kMovedLaneUlps
                << ": mono + a * shift of x), " << r.movedLaneComponents << " compared\n";
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

}  // namespace

// The run happens in a forked child: a shader that reads memory outside what the harness gave it
// (an address computed in the shader, an index past an array without robustness) crashes the
// driver's compiled code, and the user is told so, with the file, instead of getting a bare
// "Segmentation fault". STEREOSHIFT_NO_FORK=1 keeps it in this process, for a debugger.
int runVerifyCommand(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                     const VerifyCommandOptions& verify) {
  if (const char* noFork = std::getenv("STEREOSHIFT_NO_FORK"); noFork && *noFork && std::string(noFork) != "0")
    return verifyInThisProcess(sources, options, verify);
  std::cout.flush();
  std::cerr.flush();
  TaskOutcome outcome = runIsolatedOnce(
      [&] {
        const int status = verifyInThisProcess(sources, options, verify);
        std::cout.flush();
        std::cerr.flush();
        return std::to_string(status);
      },
      0);
  if (outcome.completed && (outcome.payload == "0" || outcome.payload == "1")) return std::stoi(outcome.payload);
  const std::string name = sources.empty() ? std::string("verify") : joinedPaths(sources);
  std::cerr << name << ": error: the verification run " << (outcome.completed ? "answered garbage" : outcome.failure)
            << (outcome.phase.empty() ? "" : " in " + outcome.phase)
            << "; a crash while the shaders run on the device means they read memory outside the buffers the "
               "harness gave them (an address or an index the inputs do not make valid)\n1 error generated.\n";
  return 1;
}

}  // namespace stereoshift
