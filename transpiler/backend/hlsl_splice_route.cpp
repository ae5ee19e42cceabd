// This turns the passes' decisions for an HLSL vertex, geometry or domain shader that comes back as
// HLSL into stereo HLSL by the source splice (splice_routes.h, hlsl_splice.h): the ShiftSpec of the
// conversion, the cbuffer the eye-params pass declared (its name and register), the halo copies, and
// for a vertex shader every other vertex entry point of the file, each converted on its own by the
// driver (a 2D one gets no shift). The Debian SPIRV-Cross cannot emit geometry and domain shaders
// at all, and what it re-emits of a vertex shader is no drop-in (output struct reordered, other
// entry points dropped).
#include "transpiler/backend/splice_routes.h"

#include "passes/shift_emitter.h"
#include "transpiler/backend/hlsl_splice.h"

#include <algorithm>
#include <string_view>

namespace stereoshift {

bool takesHlslSpliceRoute(const SourceInfo& info, TargetLanguage target) {
  return info.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl &&
         (info.stage == Stage::Vertex || info.stage == Stage::Geometry || info.stage == Stage::TessEvaluation);
}

namespace {

// What of one conversion the text cannot carry, in words, or empty when the splice renders all of
// it: any change of a pass besides the classification, the cbuffer, the shift and, for a vertex
// shader, halo copies that are the clip position itself. What any other pass changed lives only in
// the IR, which this route throws away, so a change there is refused rather than lost.
std::string spliceBlocker(const RunRecord& record, Stage stage) {
  // A per-eye camera the text names plainly (a vertex shader's, hlslCameras) is the splice's too.
  EditSet rendered = EditKind::EyeParameters | EditKind::PositionShift;
  bool inverseOf = std::any_of(record.perEyeView.cameraTexts.begin(), record.perEyeView.cameraTexts.end(),
                               [](const CameraText& c) { return c.inverseOf; });  // HLSL has no inverse() to wrap
  if (stage == Stage::Vertex && !record.perEyeView.fixed.empty() && !inverseOf &&
      record.perEyeView.cameraTexts.size() == record.perEyeView.fixed.size())
    rendered = rendered | EditKind::PerEyeCamera;
  for (const auto& pass : record.passesWithEditsBeyond(rendered)) {
    if (record.status(pass)->edits == editSet(EditKind::DerivedOutputShift) && stage == Stage::Vertex) {
      if (record.halo.derivedOutputs.empty()) continue;  // copies of the clip position: the splice shifts them too
      return "the " + pass + " pass changed the output '" + record.halo.derivedOutputs.front() +
             "', which is computed from the clip position (not a copy of it), and only the IR carries that";
    }
    return "it cannot carry what the " + pass + " pass changed";
  }
  return {};
}

// The per-eye cameras as the HLSL splice writes them (a vertex shader's, cbuffer eye parameters):
// the camera and its offset in HLSL, where SPIR-V's `v * M` is `mul(M, v)` and a product of SPIR-V
// matrices S1 * S2 the HLSL mul(M2, M1) (glslang's matrices are HLSL's transposed).
void hlslCameras(const PassContext& ctx, HlslSpliceOptions& splice) {
  const std::vector<std::string>& names = ctx.record.eyeParams.names;
  for (size_t k = 3; k < names.size(); ++k) splice.extraParams.push_back(names[k]);
  auto param = [&](int which) { return which < static_cast<int>(names.size()) ? names[static_cast<size_t>(which)] : ""; };
  for (const CameraText& c : ctx.record.perEyeView.cameraTexts) {
    HlslSpliceOptions::CameraWrap wrap;
    wrap.access = c.access;
    wrap.type = c.components == 4 ? "float4" : "float3";
    wrap.function = "stereoshift_eye_" + c.access;
    std::replace(wrap.function.begin(), wrap.function.end(), '.', '_');
    if (c.offset == CameraText::EyeOffsetParams) {
      wrap.offset = "float3(" + param(kEyeOffsetX) + ", " + param(kEyeOffsetY) + ", " + param(kEyeOffsetZ) + ")";
    } else {
      std::string matrix;
      for (const auto& m : c.matrices) matrix = matrix.empty() ? m : "mul(" + m + ", " + matrix + ")";
      if (c.offset == CameraText::InvertedClipMatrices) {
        matrix = "stereoshift_inverse(" + matrix + ")";
        splice.inverse = true;
      }
      std::string direction = "float4((" + splice.eyeSignName + " * " + splice.separationName + ") * " +
                              splice.convergenceName + ", 0.0f, 0.0f, 0.0f)";
      wrap.offset = (c.columnVectors ? "mul(" + direction + ", " + matrix + ")" : "mul(" + matrix + ", " + direction + ")") +
                    ".xyz";
    }
    splice.cameras.push_back(std::move(wrap));
  }
}

// The entry point `name` to shift with the halo copies its passes found, named as the source names
// them: glslang names the outputs of an entry point's returned struct `@entryPointOutput.<member>`
// and an `out` parameter by its own name.
HlslSplicedEntry splicedVertexEntry(const std::string& name, const RunRecord& record) {
  HlslSplicedEntry entry{name, {}, record.halo.movedLanes};
  if (!record.halo.shiftedOutputs) return entry;
  static constexpr std::string_view kReturned = "@entryPointOutput";
  for (const auto& output : *record.halo.shiftedOutputs) {
    std::string named = output.starts_with(kReturned) ? output.substr(kReturned.size()) : output;
    if (!named.empty() && std::find(entry.copies.begin(), entry.copies.end(), named) == entry.copies.end())
      entry.copies.push_back(named);
  }
  return entry;
}

std::string fallbackNote(const std::string& why) {
  return "HLSL vertex shader re-emitted by SPIRV-Cross instead of spliced into its own text: " + why +
         "; the output struct is SPIRV_Cross_Output (SV_Position last) and the file's other entry "
         "points are not in the output";
}

class HlslSpliceRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "hlsl-source-splice"; }
  bool takesStereoParamsTexture() const override { return true; }
  bool needsOtherEntryPoints() const override { return true; }

  RouteDecision accepts(const EmitRequest& r) const override {
    const SourceInfo& info = r.context.source;
    if (!takesHlslSpliceRoute(info, r.target)) return RouteDecision::decline("not HLSL kept as HLSL");
    bool vertex = info.stage == Stage::Vertex;
    if (r.context.eye.source != EyeSource::UniformBlock) {
      if (vertex)
        return RouteDecision::decline(
            fallbackNote("the splice declares the eye parameters only as a cbuffer (--eye-source=uniform-block)"), true);
      return RouteDecision::refuse(
          "HLSL geometry and domain shaders take the source-splice route, which supports only --eye-source=uniform-block");
    }
    if (std::string blocker = spliceBlocker(r.context.record, info.stage); !blocker.empty()) {
      if (vertex) return RouteDecision::decline(fallbackNote(blocker), true);
      return RouteDecision::refuse("HLSL geometry and domain shaders take the source-splice route, which renders only "
                                   "the clip-position shift: " + blocker + " (turn that pass off, or choose another --target)");
    }
    return RouteDecision::accept();
  }

  EmitResult emit(const EmitRequest& r, EmitFacts& facts, Diagnostics& diags) const override {
    EmitResult result;
    const PassContext& ctx = r.context;
    const SourceInfo& info = ctx.source;
    std::vector<HlslSplicedEntry> shifted;
    std::vector<std::pair<std::string, Stage>> toCheck = {{info.entryPoint, info.stage}};
    std::map<std::string, EntryPointFacts> entries;
    if (info.stage == Stage::Vertex) {
      shifted.push_back(splicedVertexEntry(info.entryPoint, ctx.record));
      entries[info.entryPoint] = {stageName(info.stage), std::string(toString(ctx.classification)), true, "", ""};
      if (r.otherEntries)
        for (OtherEntryPoint& other : *r.otherEntries)
          if (!addOtherEntry(r, other, entries, shifted, toCheck, result, diags)) return result;
    }
    Diagnostics spliceDiags;
    bool clash = false;
    if (!splice(r, shifted, result.output, facts, spliceDiags, &clash)) {
      // A clash (already injected, register taken) is refused on every route: re-emitting would
      // shift a stereo shader twice.
      if (info.stage != Stage::Vertex || clash) {
        diags.append(spliceDiags);
        result.status = EmitResult::Failed;
        return result;
      }
      // The text has something the splice does not read (a halo copy it cannot place, a struct
      // defined after its use...): SPIRV-Cross re-emits it from the IR, which carries everything.
      std::string why = spliceDiags.hasErrors() ? spliceDiags.all().front().message : "the splice failed";
      result.status = EmitResult::Declined;
      result.declinedBecause = fallbackNote(why);
      result.output.clear();
      return result;
    }
    if (info.stage == Stage::Vertex) facts.entryPoints = std::move(entries);
    // Every shifted entry point of the stereo text is re-compiled: a splice that does not compile is
    // never written.
    for (const auto& [entry, stage] : toCheck) {
      CompileCheck check;
      check.text = result.output;
      check.language = SourceLanguage::Hlsl;
      check.stage = stage;
      check.entryPoint = entry;
      check.vulkanSemantics = true;
      check.blankEffects = true;
      check.includeFrom = r.input.path;
      check.failure = "the stereo HLSL of entry point '" + entry + "' does not compile";
      result.checks.push_back(std::move(check));
    }
    result.reportsVerified = r.options.verify;
    result.status = EmitResult::Emitted;
    return result;
  }

 private:
  // One more entry point of the file: listed, and shifted when it is a vertex entry point whose own
  // conversion shifts it. False when the whole route stops (`result` says how).
  static bool addOtherEntry(const EmitRequest& r, OtherEntryPoint& other, std::map<std::string, EntryPointFacts>& entries,
                            std::vector<HlslSplicedEntry>& shifted, std::vector<std::pair<std::string, Stage>>& toCheck,
                            EmitResult& result, Diagnostics& diags) {
    const SourceInfo& info = r.context.source;
    EntryPointFacts& facts = entries[other.name];
    facts = {stageName(other.stage), std::nullopt, false, other.foundBy, ""};
    if (other.stage != Stage::Vertex) {
      if (other.stage == Stage::Geometry || other.stage == Stage::TessEvaluation)
        facts.note = "not shifted in a conversion of the vertex entry point '" + info.entryPoint + "'; convert it with -e " +
                     other.name + " -S " + stageName(other.stage);
      return true;
    }
    if (!r.entryPointOption.empty()) {
      facts.note = "not shifted: -e " + r.entryPointOption + " names another entry point";
      return true;
    }
    if (!other.ok) {
      diags.append(other.diags);
      diags.error(r.input.path, "entry point '" + other.name + "' of this file does not convert (each vertex entry point "
                                "is converted on its own; name one with -e to convert only that one)");
      result.status = EmitResult::Failed;
      return false;
    }
    facts.classification = toString(other.context->classification);
    if (!(other.changed && other.context->shiftPosition)) return true;
    if (std::string why = spliceBlocker(other.context->record, Stage::Vertex); !why.empty()) {
      result.status = EmitResult::Declined;
      result.declinedBecause = fallbackNote("entry point '" + other.name + "': " + why);
      return false;
    }
    facts.shifted = true;
    shifted.push_back(splicedVertexEntry(other.name, other.context->record));
    toCheck.push_back({other.name, Stage::Vertex});
    return true;
  }

  // Splices the shift into the input as the passes set it up (the eye parameters they declared,
  // their names and register).
  static bool splice(const EmitRequest& r, const std::vector<HlslSplicedEntry>& vertexEntries, std::string& output,
                     EmitFacts& facts, Diagnostics& diags, bool* clash) {
    const PassContext& ctx = r.context;
    const spirv::Module& module = ctx.module;
    HlslSpliceOptions splice;
    static_cast<ShiftSpec&>(splice) = shiftSpec(ctx);
    splice.entryPoint = ctx.source.entryPoint;
    splice.geometry = ctx.source.stage == Stage::Geometry;
    splice.vertex = ctx.source.stage == Stage::Vertex;
    splice.vertexEntries = vertexEntries;
    splice.cbufferName = module.name(module.pointeeType(module.definition(ctx.eye.variable)->typeId));
    splice.cbufferRegister = module.decorationValue(ctx.eye.variable, spv::DecorationBinding).value_or(0);
    if (r.options.eyeFrom3DMigoto) useStereoParamsTexture(splice);
    splice.correctionsOnly = ctx.options.correctionsOnly;
    if (splice.vertex && !splice.stereoParamsTexture) hlslCameras(ctx, splice);
    HlslSpliceResult spliced = spliceHlslStereo(r.input.contents, splice);
    if (!spliced.ok) {
      diags.error(r.input.path, spliced.line, spliced.column, "cannot splice the stereo shift: " + spliced.error);
      *clash = spliced.clash;
      return false;
    }
    output = std::move(spliced.text);
    facts.route = "hlsl-source-splice";
    facts.spliceSites = spliced.sites;
    return true;
  }
};

}  // namespace

std::unique_ptr<BackEndRoute> createHlslSpliceRoute() { return std::make_unique<HlslSpliceRoute>(); }

}  // namespace stereoshift
