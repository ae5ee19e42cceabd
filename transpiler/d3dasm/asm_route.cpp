#include "transpiler/d3dasm/asm_route.h"

#include "transpiler/d3dasm/asm_wellformed.h"

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

Result<ConvertedAssembly> convertAssembly(const SourceFile& input, const TranspileOptions& options, StageRecord& record,
                                          Diagnostics& diags) {
  record.file = input.path;
  // What the assembler would refuse when 3Dmigoto loads the dump is refused here, located.
  if (Result<d3dasm::AsmText> parsed = d3dasm::parseAssembly(input.contents); parsed.ok() && parsed->model.major >= 4)
    if (auto error = d3dasm::findAssemblerError(*parsed)) return errorAt(error->line, error->column, error->message);
  d3dasm::AsmShiftResult shifted = d3dasm::shiftAssembly(input.contents, assemblyShiftSpec(options),
                                                         options.deferredUnprojection, !options.correctionsOnly);
  if (!shifted.ok) return errorAt(shifted.error.line, shifted.error.column, shifted.error.message);
  const std::optional<Stage> stage = shifted.stage;
  record.stage = stage;
  record.stageReason = "shader model line " + shifted.model;
  StageRecord::Assembly assembly;
  assembly.shaderModel = shifted.model;
  assembly.leftAlone = shifted.leftAlone;
  if (options.stage && stage && *options.stage != *stage)
    return errorAt(shifted.modelLine, 1,
                   "-S " + std::string(stageName(*options.stage)) + " contradicts the shader model line " + shifted.model);
  if (std::string why = unsupportedOption(options); !why.empty()) return errorAt(0, 0, why);
  record.emit.route = "d3d-asm-splice";
  if (shifted.alreadyStereo) diags.warning(input.path, shifted.whyUnchanged + " (copied unchanged)");
  if (!shifted.corrections.empty()) {
    // A pixel shader's corrections: per-eye fixes, made whether or not the driver shifts the
    // vertices (--corrections-only) and whichever stage of a pipeline is shifted.
    for (const auto& c : shifted.corrections)
      assembly.corrections.push_back({c.form, c.matrix, c.depth, c.ndc, c.fix, c.firstLine, c.lastLine});
    assembly.declaredStereoParams = shifted.declaredStereoParams;
    record.assembly = assembly;
    record.emit.spliceSites = shifted.sites;
    record.output = StageRecord::Output::Emitted;
    record.changed = true;
    return ConvertedAssembly{std::move(shifted.output), false};
  }
  if (!shifted.shifted || !options.shiftThisStage) {
    assembly.unchangedBecause = !shifted.shifted ? shifted.whyUnchanged : "an earlier stage of the pipeline";
    record.assembly = assembly;
    record.output = StageRecord::Output::Copied;
    return ConvertedAssembly{input.contents, true};
  }
  assembly.positionRegister = shifted.positionRegister;
  assembly.positionTemp = shifted.positionTemp;
  assembly.redirectedWrites = shifted.redirectedWrites;
  assembly.declaredStereoParams = shifted.declaredStereoParams;
  assembly.movedLanes = shifted.movedLanes;
  assembly.positionLeftToDriver = !shifted.positionShifted;
  assembly.notDone = {"2D proof (the runtime cutoff keeps w = 1 draws mono)",
                      "halos other than copies and lanes linear in x with a constant coefficient", "per-eye fixes"};
  record.assembly = assembly;
  record.emit.spliceSites = shifted.sites;
  record.output = StageRecord::Output::Emitted;
  record.changed = true;
  return ConvertedAssembly{std::move(shifted.output), false};
}

}  // namespace stereoshift
