// This turns the passes' decisions for an HLSL geometry or domain shader into stereo HLSL by the
// source splice (see splice_route.h): the ShiftSpec of the conversion, the cbuffer the eye-params
// pass declared (its name and register), and a refusal for whatever the text cannot carry.
#include "transpiler/backend/splice_route.h"

#include "transpiler/backend/hlsl_splice.h"

#include <string_view>

namespace stereoshift {

namespace {

// The passes whose work the splice re-renders as text: the classification, the cbuffer and the
// clip-position shift. What any other pass changed lives only in the IR, which this route throws
// away, so a change there is refused rather than lost.
bool splicedAsText(std::string_view pass) {
  return pass == "clip-position-detection" || pass == "eye-params" || pass == "stereo-shift";
}

}  // namespace

bool takesSourceSpliceRoute(const SourceInfo& info, TargetLanguage target) {
  return info.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl &&
         (info.stage == Stage::Geometry || info.stage == Stage::TessEvaluation);
}

bool spliceSourceStereo(const SourceFile& input, const PassContext& context, std::string& output,
                        nlohmann::json& report, Diagnostics& diags) {
  const std::string& file = input.path;
  const spirv::Module& module = context.module;
  if (context.eye.source != EyeSource::UniformBlock) {
    diags.error(file, "HLSL geometry and domain shaders take the source-splice route, which supports only "
                      "--eye-source=uniform-block");
    return false;
  }
  if (report.contains("passes")) {
    for (const auto& [pass, facts] : report["passes"].items()) {
      if (splicedAsText(pass) || !facts.contains("result") || facts["result"] != "changed") continue;
      diags.error(file, "HLSL geometry and domain shaders take the source-splice route, which renders only the "
                        "clip-position shift: it cannot carry what the " + pass + " pass changed (turn that pass off, or "
                        "choose another --target)");
      return false;
    }
  }
  HlslSpliceOptions splice;
  static_cast<ShiftSpec&>(splice) = shiftSpec(context);
  splice.entryPoint = context.source.entryPoint;
  splice.geometry = context.source.stage == Stage::Geometry;
  splice.cbufferName = module.name(module.pointeeType(module.definition(context.eye.variable)->typeId));
  splice.cbufferRegister = module.decorationValue(context.eye.variable, spv::DecorationBinding).value_or(0);
  HlslSpliceResult spliced = spliceHlslStereo(input.contents, splice);
  if (!spliced.ok) {
    diags.error(file, spliced.line, spliced.column, "cannot splice the stereo shift: " + spliced.error);
    return false;
  }
  output = std::move(spliced.text);
  report["route"] = "hlsl-source-splice";
  report["passes"]["stereo-shift"]["sites"] = spliced.sites;
  return true;
}

}  // namespace stereoshift
