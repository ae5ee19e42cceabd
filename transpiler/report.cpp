// See report.h: the one place that spells the report's keys.
#include "transpiler/report.h"

#include "transpiler/frontend/language_detect.h"

namespace stereoshift {

using nlohmann::json;

const char* languageName(SourceLanguage language) {
  switch (language) {
    case SourceLanguage::Glsl: return "glsl";
    case SourceLanguage::Hlsl: return "hlsl";
    case SourceLanguage::Spirv: return "spirv";
  }
  return "?";
}

const char* targetName(TargetLanguage target) {
  switch (target) {
    case TargetLanguage::Auto: return "auto";
    case TargetLanguage::Glsl: return "glsl";
    case TargetLanguage::Essl: return "essl";
    case TargetLanguage::Hlsl: return "hlsl";
    case TargetLanguage::Msl: return "msl";
    case TargetLanguage::Spirv: return "spirv";
    case TargetLanguage::SpirvAsm: return "spirv-asm";
  }
  return "?";
}

namespace {

json renderUse(const ViewDependentUse& use) {
  json entry = json::object();
  auto text = [&](const char* key, const std::optional<std::string>& value) {
    if (value) entry[key] = *value;
  };
  text("construct", use.construct);
  text("uniform", use.uniform);
  text("name_hint", use.nameHint);
  text("use", use.use);
  text("reason", use.reason);
  text("why", use.why);
  text("form", use.form);
  text("matrix", use.matrix);
  text("depth", use.depth);
  text("depth_range", use.depthRange);
  text("ndc", use.ndc);
  text("fix", use.fix);
  text("projection_scale", use.projectionScale);
  text("reaches", use.reaches);
  text("eye_centre", use.eyeCentre);
  if (use.count) entry["count"] = *use.count;
  if (use.loadsReplaced) entry["loads_replaced"] = *use.loadsReplaced;
  if (use.line) entry["line"] = *use.line;
  return entry;
}

json renderUses(const std::vector<ViewDependentUse>& uses) {
  json list = json::array();
  for (const auto& use : uses) list.push_back(renderUse(use));
  return list;
}

void renderDetection(const RunRecord& record, json& passes) {
  const DetectionFacts& facts = record.detection;
  if (!facts.classification) return;
  json& out = passes["clip-position-detection"];
  out["positions"] = facts.positions;
  out["classification"] = toString(*facts.classification);
  if (!facts.alreadyStereo.empty()) out["already_stereo"] = facts.alreadyStereo;
  if (facts.leftToDriver) out["position_left_to_driver"] = "--corrections-only: the driver shifts it";
}

void renderHudAtDepth(const RunRecord& record, json& passes) {
  const HudAtDepthFacts& facts = record.hudAtDepth;
  if (facts.stores) {
    json& out = passes["hud-at-depth"];
    out["placed_at_depth"] = facts.placedAtDepth;
    out["stores"] = *facts.stores;
    out["position"] = facts.position;
    if (!facts.note.empty()) out["note"] = facts.note;
  }
  if (!facts.leftAlone.empty()) passes["hud-at-depth"]["left_alone"] = facts.leftAlone;
}

void renderSinglePass(const RunRecord& record, json& passes) {
  const SinglePassFacts& facts = record.singlePass;
  if (facts.mode.empty()) return;
  json& out = passes["single-pass-stereo"];
  out["mode"] = facts.mode;
  if (facts.eyeVaryingName) out["eye_varying"] = {{"name", *facts.eyeVaryingName}, {"location", facts.eyeVaryingLocation}};
  if (facts.emitsRouted) out["emits_routed"] = *facts.emitsRouted;
  if (!facts.eyeWrittenTo.empty()) out["eye_written_to"] = facts.eyeWrittenTo;
  if (facts.eyeHandedOn) out["eye_handed_on"] = true;
  if (!facts.requiredExtension.empty()) out["requires"] = facts.requiredExtension;
  if (facts.instanceReadsRewritten) out["instance_reads_rewritten"] = *facts.instanceReadsRewritten;
}

void renderEyeParams(const RunRecord& record, json& passes) {
  const EyeParamFacts& facts = record.eyeParams;
  if (facts.declared.empty() && facts.renamed.empty() && facts.names.empty()) return;
  json& out = passes["eye-params"];
  if (!facts.declared.empty()) out["declared"] = facts.declared;
  if (facts.pushConstantOffset) out["offset"] = *facts.pushConstantOffset;
  if (facts.declared == "uniform block") {
    out["block"] = facts.block;
    out["instance"] = facts.instance;
  }
  if (facts.set) out["set"] = *facts.set;
  if (facts.binding) out["binding"] = *facts.binding;
  for (const auto& [wanted, chosen] : facts.renamed) out["renamed"][wanted] = chosen;
  if (!facts.specIds.empty()) out["specIds"] = facts.specIds;
  if (!facts.names.empty()) out["names"] = facts.names;
}

void renderHaloAndShift(const RunRecord& record, std::optional<int> spliceSites, json& passes) {
  if (record.halo.shiftedOutputs) passes["halo"]["shifted_outputs"] = *record.halo.shiftedOutputs;
  if (!record.halo.derivedOutputs.empty()) passes["halo"]["derived_outputs"] = record.halo.derivedOutputs;
  for (const auto& moved : record.halo.movedLanes)
    passes["halo"]["moved_lanes"].push_back(
        {{"output", moved.output}, {"lane", std::string(1, "xyzw"[moved.lane & 3])}, {"coefficient", moved.coefficient}});
  const ShiftFacts& shift = record.shift;
  if (spliceSites) passes["stereo-shift"]["sites"] = *spliceSites;
  else if (shift.sites) passes["stereo-shift"]["sites"] = *shift.sites;
  if (!shift.form.empty()) passes["stereo-shift"]["form"] = shift.form;
}

void renderPerEyeView(const RunRecord& record, json& passes) {
  const PerEyeViewFacts& facts = record.perEyeView;
  auto out = [&]() -> json& { return passes["per-eye-view"]; };
  if (!facts.fixed.empty()) out()["fixed"] = renderUses(facts.fixed);
  if (!facts.leftAlone.empty()) out()["left_alone"] = renderUses(facts.leftAlone);
  if (!facts.skipped.empty()) out()["skipped"] = facts.skipped;
  if (!facts.forcedCameraNotFound.empty()) out()["forced_camera_not_found"] = facts.forcedCameraNotFound;
  if (!facts.perEyeOutputs.empty()) out()["per_eye_outputs"] = facts.perEyeOutputs;
  if (!facts.application.empty()) out()["application"] = facts.application;
}

void renderDeferred(const RunRecord& record, json& passes) {
  const DeferredFacts& facts = record.deferred;
  auto out = [&]() -> json& { return passes["deferred-unprojection"]; };
  if (!facts.leftAloneWhy.empty()) out()["left_alone"] = facts.leftAloneWhy;
  if (!facts.fixed.empty()) out()["fixed"] = renderUses(facts.fixed);
  if (!facts.leftAlone.empty()) out()["left_alone"] = renderUses(facts.leftAlone);
  if (!facts.applicationFills.empty()) out()["application_fills"] = facts.applicationFills;
}

json renderEntryPoints(const std::map<std::string, EntryPointFacts>& entries) {
  json out = json::object();
  for (const auto& [name, facts] : entries) {
    json& entry = out[name];
    entry["stage"] = facts.stage;
    if (facts.classification) entry["classification"] = *facts.classification;
    entry["shifted"] = facts.shifted;
    if (!facts.foundBy.empty()) entry["found_by"] = facts.foundBy;
    if (!facts.note.empty()) entry["note"] = facts.note;
  }
  return out;
}

void renderEmitFacts(const EmitFacts& emit, json& report) {
  if (!emit.route.empty()) report["route"] = emit.route;
  for (const auto& note : emit.notes) report["notes"].push_back(note);
  if (emit.entryPoints) report["entry_points"] = renderEntryPoints(*emit.entryPoints);
  if (!emit.haloCopies.empty()) report["halo_copies"] = emit.haloCopies;
  if (!emit.notCarried.empty()) report["not_carried"] = emit.notCarried;
}

}  // namespace

json renderPassReport(const RunRecord& record, std::optional<int> spliceSites) {
  json passes = json::object();
  for (const auto& status : record.passes) {
    json& out = passes[status.name];
    if (!status.requiredBy.empty()) out["required_by"] = status.requiredBy;
    out["result"] = toString(status.result);
  }
  renderDetection(record, passes);
  renderHudAtDepth(record, passes);
  renderSinglePass(record, passes);
  renderEyeParams(record, passes);
  renderHaloAndShift(record, spliceSites, passes);
  renderPerEyeView(record, passes);
  renderDeferred(record, passes);
  return passes;
}

json renderStageReport(const StageRecord& record) {
  json report = json::object();
  report["file"] = record.file;
  if (record.languageDecided) {
    report["language"] = languageName(record.language);
    report["language_source"] = languageSourceName(record.languageSource);
    report["language_reason"] = record.languageReason;
  }
  if (!record.dialectReason.empty()) report["dialect_reason"] = record.dialectReason;
  if (!record.includedFiles.empty()) report["included_files"] = record.includedFiles;
  if (record.frontEndMs) report["timings_ms"]["front_end"] = *record.frontEndMs;
  if (record.passesMs) report["timings_ms"]["passes"] = *record.passesMs;
  if (record.backEndMs) report["timings_ms"]["back_end"] = *record.backEndMs;
  if (record.totalMs) report["timings_ms"]["total"] = *record.totalMs;
  if (record.stage) {
    report["stage"] = stageName(*record.stage);
    report["stage_reason"] = record.stageReason;
  }
  if (!record.dialect.empty()) report["dialect"] = record.dialect;
  if (record.versionRaised)
    report["version_raised"] = {{"from", record.versionRaised->from}, {"to", record.versionRaised->to},
                                {"why", record.versionRaised->why}};
  if (record.passesRan) report["passes"] = renderPassReport(record.passes, record.emit.spliceSites);
  if (record.classification) {
    report["classification"] = toString(*record.classification);
    report["changed"] = record.changed;
  }
  if (record.target) report["target"] = targetName(*record.target);
  if (!record.frontEndSpirvInvalid.empty()) report["front_end_spirv_invalid"] = record.frontEndSpirvInvalid;
  renderEmitFacts(record.emit, report);
  if (!record.lifted.empty()) {
    report["analysis"] = "lifted";
    report["lifted"] = record.lifted;
  }
  if (record.textOnly) {
    report["analysis"] = record.textOnly->unanalysed ? "none" : "text-only";
    report["analysis_reason"] = record.textOnly->reason;
    report["not_done"] = record.textOnly->notDone;
    report["eye_params"] = record.textOnly->eyeParams;
  }
  if (record.assembly) {
    const StageRecord::Assembly& a = *record.assembly;
    report["language"] = "d3d-asm";
    report["analysis"] = "d3d-assembly";
    report["shader_model"] = a.shaderModel;
    if (!a.positionRegister.empty()) {
      report["position_register"] = a.positionRegister;
      report["position_temp"] = a.positionTemp;
      report["redirected_writes"] = a.redirectedWrites;
      report["eye_params"] = a.declaredStereoParams ? "3Dmigoto StereoParams texture (t125, declared)"
                                                    : "3Dmigoto StereoParams texture (t125, the dump's)";
      report["not_done"] = a.notDone;
      for (const auto& moved : a.movedLanes)
        report["moved_lanes"].push_back({{"output", "o" + std::to_string(moved.reg)},
                                         {"lane", std::string(1, "xyzw"[moved.lane & 3])},
                                         {"coefficient", moved.coefficient},
                                         {"copy", moved.copy},
                                         {"line", moved.line}});
      if (a.positionLeftToDriver) report["position_left_to_driver"] = "--corrections-only: the driver shifts it";
    }
    if (!a.corrections.empty()) {
      nlohmann::json fixed = nlohmann::json::array();
      for (const auto& c : a.corrections) {
        nlohmann::json entry = {{"form", c.form}, {"depth", c.depth}, {"ndc", c.ndc}, {"fix", c.fix},
                                {"lines", std::to_string(c.firstLine) + "-" + std::to_string(c.lastLine)}};
        if (!c.matrix.empty()) entry["matrix"] = c.matrix;
        fixed.push_back(std::move(entry));
      }
      report["corrections"] = {{"deferred-unprojection", std::move(fixed)}};
      report["eye_params"] = a.declaredStereoParams ? "3Dmigoto StereoParams texture (t125, declared)"
                                                    : "3Dmigoto StereoParams texture (t125, the dump's)";
    }
    if (!a.leftAlone.empty()) report["left_alone"] = a.leftAlone;
    if (!a.unchangedBecause.empty()) report["unchanged_because"] = a.unchangedBecause;
  }
  if (record.mesa) {
    report["mesa"] = {{"original", record.mesa->original}};
    if (!record.mesa->output.empty()) report["mesa"]["output"] = record.mesa->output;
    if (!record.mesa->driver.empty()) report["mesa"]["driver"] = record.mesa->driver;
    if (!record.mesa->readAt.empty()) report["mesa"]["read_at"] = record.mesa->readAt;
  }
  if (record.output == StageRecord::Output::Copied) report["output"] = "copied";
  if (record.output == StageRecord::Output::Emitted) report["output"] = "emitted";
  if (record.verified) report["verified"] = true;
  return report;
}

}  // namespace stereoshift
