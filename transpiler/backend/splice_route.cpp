// This turns the passes' decisions for an HLSL vertex, geometry or domain shader into stereo HLSL
// by the source splice (see splice_route.h): the ShiftSpec of the conversion, the cbuffer the
// eye-params pass declared (its name and register), the halo copies, and a refusal for whatever
// the text cannot carry.
#include "transpiler/backend/splice_route.h"

#include "transpiler/backend/hlsl_splice.h"

#include <algorithm>
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
         (info.stage == Stage::Vertex || info.stage == Stage::Geometry || info.stage == Stage::TessEvaluation);
}

std::string spliceBlocker(const nlohmann::json& passes, Stage stage) {
  for (const auto& [pass, facts] : passes.items()) {
    if (splicedAsText(pass) || !facts.contains("result") || facts["result"] != "changed") continue;
    if (pass == "halo" && stage == Stage::Vertex) {
      if (!facts.contains("derived_outputs")) continue;  // copies of the clip position: the splice shifts them too
      return "the halo pass changed the output '" + facts["derived_outputs"].front().get<std::string>() +
             "', which is computed from the clip position (not a copy of it), and only the IR carries that";
    }
    return "it cannot carry what the " + pass + " pass changed";
  }
  return {};
}

HlslSplicedEntry splicedVertexEntry(const std::string& name, const nlohmann::json& passes) {
  HlslSplicedEntry entry{name, {}};
  if (!passes.contains("halo") || !passes["halo"].contains("shifted_outputs")) return entry;
  // glslang names the outputs of an entry point's returned struct `@entryPointOutput.<member>`
  // and an `out` parameter by its own name.
  static constexpr std::string_view kReturned = "@entryPointOutput";
  for (const auto& copy : passes["halo"]["shifted_outputs"]) {
    std::string output = copy.get<std::string>();
    std::string named = output.starts_with(kReturned) ? output.substr(kReturned.size()) : output;
    if (!named.empty() && std::find(entry.copies.begin(), entry.copies.end(), named) == entry.copies.end())
      entry.copies.push_back(named);
  }
  return entry;
}

bool spliceSourceStereo(const SourceFile& input, const PassContext& context,
                        const std::vector<HlslSplicedEntry>& vertexEntries, std::string& output,
                        nlohmann::json& report, Diagnostics& diags, bool* clash) {
  const std::string& file = input.path;
  const spirv::Module& module = context.module;
  const char* route = context.source.stage == Stage::Vertex ? "HLSL vertex shaders" : "HLSL geometry and domain shaders";
  if (context.eye.source != EyeSource::UniformBlock) {
    diags.error(file, std::string(route) + " take the source-splice route, which supports only "
                      "--eye-source=uniform-block");
    return false;
  }
  if (report.contains("passes")) {
    if (std::string blocker = spliceBlocker(report["passes"], context.source.stage); !blocker.empty()) {
      diags.error(file, std::string(route) + " take the source-splice route, which renders only the "
                        "clip-position shift: " + blocker + " (turn that pass off, or choose another --target)");
      return false;
    }
  }
  HlslSpliceOptions splice;
  static_cast<ShiftSpec&>(splice) = shiftSpec(context);
  splice.entryPoint = context.source.entryPoint;
  splice.geometry = context.source.stage == Stage::Geometry;
  splice.vertex = context.source.stage == Stage::Vertex;
  splice.vertexEntries = vertexEntries;
  splice.cbufferName = module.name(module.pointeeType(module.definition(context.eye.variable)->typeId));
  splice.cbufferRegister = module.decorationValue(context.eye.variable, spv::DecorationBinding).value_or(0);
  HlslSpliceResult spliced = spliceHlslStereo(input.contents, splice);
  if (!spliced.ok) {
    diags.error(file, spliced.line, spliced.column, "cannot splice the stereo shift: " + spliced.error);
    if (clash) *clash = spliced.clash;
    return false;
  }
  output = std::move(spliced.text);
  report["route"] = "hlsl-source-splice";
  report["passes"]["stereo-shift"]["sites"] = spliced.sites;
  return true;
}

}  // namespace stereoshift
