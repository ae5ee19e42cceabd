#include "transpiler/d3dasm/asm_route.h"

#include <chrono>

namespace stereoshift {

std::optional<Stage> assemblyStage(const SourceFile& input) {
  Result<d3dasm::AsmText> text = d3dasm::parseAssembly(input.contents);
  if (!text) return std::nullopt;
  return d3dasm::stageOfShaderModel(text->model);
}

ShiftSpec assemblyShiftSpec(const TranspileOptions& options) {
  ShiftSpec spec;
  spec.cutoff = normalisedCutoff(options.cutoff, options.cutoffEpsilon);
  spec.epsilon = options.cutoffEpsilon;
  return spec;
}

namespace {

// Why the options ask for something the assembly route cannot write, or "".
std::string unsupportedOption(const TranspileOptions& options) {
  if (options.target != TargetLanguage::Auto)
    return "D3D shader assembly is written back as assembly: --target " + std::string(targetName(options.target)) +
           " is not available for it";
  if (options.eye.select != EyeSelect::Parameter)
    return "single-pass stereo (--eye-source multiview / instanced) is not available for D3D shader assembly";
  if (options.eye.source != EyeSource::Auto && !options.eyeFrom3DMigoto)
    return "the assembly route reads the eye parameters from 3Dmigoto's StereoParams texture (t125): use "
           "--eye-source 3dmigoto (or leave --eye-source out)";
  return "";
}

}  // namespace

TranspileResult convertAssemblyStage(const SourceFile& input, const TranspileOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  TranspileResult result;
  StageRecord& record = result.record;
  record.file = input.path;
  auto fail = [&](int line, int column, const std::string& message) {
    result.diagnostics.error(input.path, line, column, message);
    result.report = renderStageReport(record);
    return result;
  };
  d3dasm::AsmShiftResult shifted = d3dasm::shiftAssembly(input.contents, assemblyShiftSpec(options));
  if (!shifted.ok)
    return fail(static_cast<int>(shifted.error.line), static_cast<int>(shifted.error.column), shifted.error.message);
  const std::optional<Stage> stage = shifted.stage;
  record.stage = stage;
  record.stageReason = "shader model line " + shifted.model;
  StageRecord::Assembly assembly;
  assembly.shaderModel = shifted.model;
  if (options.stage && stage && *options.stage != *stage)
    return fail(static_cast<int>(shifted.modelLine), 1,
                "-S " + std::string(stageName(*options.stage)) + " contradicts the shader model line " + shifted.model);
  if (std::string why = unsupportedOption(options); !why.empty()) return fail(0, 0, why);
  record.emit.route = "d3d-asm-splice";
  if (shifted.alreadyStereo)
    result.diagnostics.warning(input.path, shifted.whyUnchanged + " (copied unchanged)");
  if (!shifted.shifted || !options.shiftThisStage || options.correctionsOnly) {
    assembly.unchangedBecause = !shifted.shifted          ? shifted.whyUnchanged
                                : options.correctionsOnly ? "--corrections-only: the position is left to the driver's shift"
                                                          : "an earlier stage of the pipeline";
    record.assembly = assembly;
    record.output = StageRecord::Output::Copied;
    result.ok = true;
    result.copiedThrough = true;
    result.output = input.contents;
  } else {
    assembly.positionRegister = shifted.positionRegister;
    assembly.positionTemp = shifted.positionTemp;
    assembly.redirectedWrites = shifted.redirectedWrites;
    assembly.declaredStereoParams = shifted.declaredStereoParams;
    assembly.notDone = {"2D proof (the runtime cutoff keeps w = 1 draws mono)", "halo copies of the position",
                        "per-eye fixes"};
    record.assembly = assembly;
    record.emit.spliceSites = shifted.sites;
    record.output = StageRecord::Output::Emitted;
    record.changed = true;
    result.ok = true;
    result.changed = true;
    result.output = std::move(shifted.output);
  }
  record.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  result.report = renderStageReport(record);
  return result;
}

}  // namespace stereoshift
