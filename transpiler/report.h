// The per-stage report: what the driver decided and what each part did, as typed facts
// (StageRecord), and the one function that renders them as the JSON report users and tools read
// (`--report`, `build`'s stereoshift-report.json). No part of the tool reads the JSON back: the
// record is the interface, the JSON its rendering.
#pragma once

#include "passes/run_record.h"
#include "core/shader.h"
#include "transpiler/backend/emit_facts.h"
#include "transpiler/d3dasm/asm_halo.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

struct StageRecord {
  std::string file;
  // The language decision (also when the shader does not parse: it is often why).
  bool languageDecided = false;
  SourceLanguage language = SourceLanguage::Glsl;
  LanguageSource languageSource = LanguageSource::Extension;
  std::string languageReason;
  std::string dialectReason;               // GLSL without #version or below 330: why this dialect
  std::vector<std::string> includedFiles;
  std::optional<double> frontEndMs, passesMs, backEndMs, totalMs;
  // Known once the module parsed:
  std::optional<Stage> stage;
  std::string stageReason;
  std::string dialect;                     // GLSL: "450 vulkan", "300 es", ...
  struct VersionRaise {
    int from = 0, to = 0;
    std::string why;
  };
  std::optional<VersionRaise> versionRaised;
  // Known once the passes ran to the end:
  bool passesRan = false;                  // the pass pipeline started (its statuses are in `passes`)
  RunRecord passes;
  std::optional<Classification> classification;
  bool changed = false;
  std::optional<TargetLanguage> target;
  // The back end:
  std::string frontEndSpirvInvalid;        // glslang's module does not validate (and why)
  EmitFacts emit;
  // Shifted from the text alone (text_only_shift.h): the front end's reason, what was not done.
  // `unanalysed`: a stage that takes no shift, copied unchanged without an analysis ("analysis": "none").
  struct TextOnly {
    std::string reason;
    std::vector<std::string> notDone;
    std::string eyeParams;
    bool unanalysed = false;
  };
  std::optional<TextOnly> textOnly;
  // D3D shader assembly, edited by the assembly route (d3dasm/asm_shift.h): no SPIR-V analysis ran;
  // the position is the declared one.
  struct Assembly {
    std::string shaderModel;        // "vs_5_0"
    std::string positionRegister;   // "o0"; empty when the stage has none
    std::string positionTemp;       // the temporary its writes go to
    int redirectedWrites = 0;
    bool declaredStereoParams = false;
    std::string unchangedBecause;   // copied as it is: why
    std::vector<std::string> notDone;
    // A pixel shader: the position rebuilds corrected (d3dasm/asm_unprojection.h).
    struct Correction {
      std::string form, matrix, depth, ndc, fix;
      size_t firstLine = 0, lastLine = 0;
    };
    std::vector<Correction> corrections;
    std::vector<std::string> leftAlone;  // seen in a pixel shader and left for a person, with why
    // A vertex or domain shader: output lanes moved with the position's x (d3dasm/asm_halo.h), and
    // whether the position itself was left to the driver (--corrections-only).
    std::vector<d3dasm::AsmMovedLane> movedLanes;
    bool positionLeftToDriver = false;
  };
  std::optional<Assembly> assembly;
  std::string lifted;  // analysed on a lifted copy (frontend/glsl_lift.h): what was lifted
  // Mesa's word (frontend/mesa_compiler.h) on a GLSL stage a route said yes to where glslang did not:
  // "compiled", "refused", "unchecked: <why>"; the output's; the driver that gave it.
  struct MesaCheck {
    std::string original, output, driver;
    std::string readAt;  // text without #version: the version Mesa compiled it at
  };
  std::optional<MesaCheck> mesa;
  enum class Output { None, Copied, Emitted } output = Output::None;
  bool verified = false;
};

// The JSON report of one stage.
nlohmann::json renderStageReport(const StageRecord& record);
// The "passes" object of a report: each pass that ran, with its result and facts.
// `spliceSites`: the sites a source splice shifted, reported as the stereo-shift pass's own.
nlohmann::json renderPassReport(const RunRecord& record, std::optional<int> spliceSites = std::nullopt);

const char* languageName(SourceLanguage language);
const char* targetName(TargetLanguage target);

}  // namespace stereoshift
