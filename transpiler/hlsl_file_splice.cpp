// This turns a converted HLSL file into its stereo text by the source splice, every vertex entry
// point of it classified and shifted on its own (see hlsl_file_splice.h).
#include "transpiler/hlsl_file_splice.h"

#include "passes/ir/module.h"
#include "passes/pass_manager.h"
#include "transpiler/backend/back_end.h"
#include "transpiler/backend/hlsl_splice.h"
#include "transpiler/backend/splice_route.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/hlsl_effects.h"

#include <vector>

namespace stereoshift {

namespace {

// The conversion of one more vertex entry point of the file: its own front end and passes.
struct OtherEntry {
  bool ok = false;
  bool shifted = false;
  std::string classification;
  nlohmann::json passes;
};

OtherEntry convertOtherEntry(const SourceFile& input, const TranspileOptions& options, const std::string& name,
                             Diagnostics& diags) {
  OtherEntry entry;
  TranspileOptions entryOptions = options;
  entryOptions.entryPoint = name;
  entryOptions.stage = Stage::Vertex;
  FrontEndResult front = compileToSpirv(input, entryOptions, diags);
  if (!front.ok) return entry;
  std::string error;
  auto module = spirv::Module::parse(front.spirv, &error);
  if (!module) {
    diags.error(input.path, "entry point '" + name + "': " + error);
    return entry;
  }
  nlohmann::json report;
  PassContext ctx{*module, entryOptions, front.info, diags, input.path, report};
  bool changed = false;
  std::string log;
  if (!runPassPipeline(ctx, &changed, &log)) return entry;
  entry.ok = true;
  entry.shifted = changed && ctx.shiftPosition;
  entry.classification = toString(ctx.classification);
  entry.passes = report.value("passes", nlohmann::json::object());
  return entry;
}

void noteFallback(const std::string& file, const std::string& why, nlohmann::json& report, Diagnostics& diags) {
  std::string note = "HLSL vertex shader re-emitted by SPIRV-Cross instead of spliced into its own text: " + why +
                     "; the output struct is SPIRV_Cross_Output (SV_Position last) and the file's other entry "
                     "points are not in the output";
  report["notes"].push_back(note);
  diags.note(file, note);
}

}  // namespace

HlslSpliceOutcome spliceHlslFile(const SourceFile& input, PassContext& context, TargetLanguage target,
                                 std::string& output, nlohmann::json& report, Diagnostics& diags) {
  const SourceInfo& info = context.source;
  if (!takesSourceSpliceRoute(info, target)) return HlslSpliceOutcome::NotTaken;
  const std::string& file = input.path;
  const TranspileOptions& options = context.options;
  std::vector<HlslSplicedEntry> shifted;
  // Which stage each shifted entry point is re-compiled as.
  std::vector<std::pair<std::string, Stage>> toVerify = {{info.entryPoint, info.stage}};

  if (info.stage == Stage::Vertex) {
    if (context.eye.source != EyeSource::UniformBlock) {
      noteFallback(file, "the splice declares the eye parameters only as a cbuffer (--eye-source=uniform-block)",
                   report, diags);
      return HlslSpliceOutcome::NotTaken;
    }
    if (std::string why = spliceBlocker(report.value("passes", nlohmann::json::object()), Stage::Vertex);
        !why.empty()) {
      noteFallback(file, why, report, diags);
      return HlslSpliceOutcome::NotTaken;
    }
    shifted.push_back(splicedVertexEntry(info.entryPoint, report.value("passes", nlohmann::json::object())));
    nlohmann::json entries = nlohmann::json::object();
    entries[info.entryPoint] = {{"stage", stageName(info.stage)},
                                {"classification", toString(context.classification)},
                                {"shifted", true}};
    for (const HlslEntryPoint& other : findHlslEntryPoints(input.contents)) {
      if (other.name == info.entryPoint) continue;
      nlohmann::json& facts = entries[other.name];
      facts = {{"stage", stageName(other.stage)}, {"found_by", other.foundBy}, {"shifted", false}};
      if (other.stage != Stage::Vertex) {
        if (other.stage == Stage::Geometry || other.stage == Stage::TessEvaluation)
          facts["note"] = "not shifted in a conversion of the vertex entry point '" + info.entryPoint +
                          "'; convert it with -e " + other.name + " -S " + stageName(other.stage);
        continue;
      }
      if (!options.entryPoint.empty()) {
        facts["note"] = "not shifted: -e " + options.entryPoint + " names another entry point";
        continue;
      }
      Diagnostics entryDiags;
      OtherEntry converted = convertOtherEntry(input, options, other.name, entryDiags);
      if (!converted.ok) {
        diags.append(entryDiags);
        diags.error(file, "entry point '" + other.name + "' of this file does not convert (each vertex entry point "
                          "is converted on its own; name one with -e to convert only that one)");
        return HlslSpliceOutcome::Failed;
      }
      facts["classification"] = converted.classification;
      if (!converted.shifted) continue;
      if (std::string why = spliceBlocker(converted.passes, Stage::Vertex); !why.empty()) {
        noteFallback(file, "entry point '" + other.name + "': " + why, report, diags);
        return HlslSpliceOutcome::NotTaken;
      }
      facts["shifted"] = true;
      shifted.push_back(splicedVertexEntry(other.name, converted.passes));
      toVerify.push_back({other.name, Stage::Vertex});
    }
    report["entry_points"] = entries;
  }

  Diagnostics spliceDiags;
  bool clash = false;
  if (!spliceSourceStereo(input, context, shifted, output, report, spliceDiags, &clash)) {
    // A clash (already injected, register taken) is refused on every route: re-emitting would
    // shift a stereo shader twice.
    if (info.stage != Stage::Vertex || clash) {
      diags.append(spliceDiags);
      return HlslSpliceOutcome::Failed;
    }
    // The text has something the splice does not read (a halo copy it cannot place, a struct
    // defined after its use...): SPIRV-Cross re-emits it from the IR, which carries everything.
    std::string why = spliceDiags.hasErrors() ? spliceDiags.all().front().message : "the splice failed";
    report.erase("entry_points");
    noteFallback(file, why, report, diags);
    output.clear();
    return HlslSpliceOutcome::NotTaken;
  }
  // Every shifted entry point of the stereo text is re-compiled, with or without --verify: a
  // splice that does not compile is never written.
  std::string compiled = blankEffectBlocks(output);
  for (const auto& [name, stage] : toVerify) {
    Diagnostics verifyDiags;
    if (!verifyCompiles(compiled, SourceLanguage::Hlsl, stage, name, true, file + " (emitted)", verifyDiags,
                        &context.options, input.path)) {
      diags.append(verifyDiags);
      diags.error(file, "the stereo HLSL of entry point '" + name + "' does not compile");
      return HlslSpliceOutcome::Failed;
    }
  }
  if (options.verify) report["verified"] = true;
  return HlslSpliceOutcome::Spliced;
}

}  // namespace stereoshift
