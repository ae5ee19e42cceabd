// See stage_plan.h: the steps of one stage's conversion, each a function.
#include "transpiler/stage_plan.h"

#include "passes/ir/validate.h"
#include "passes/pass_manager.h"
#include "transpiler/backend/hlsl_splice.h"
#include "transpiler/backend/splice_routes.h"
#include "transpiler/text_only_shift.h"
#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/frontend/hlsl_lift.h"
#include "transpiler/frontend/legacy_glsl.h"
#include "transpiler/frontend/mesa_compiler.h"
#include "transpiler/output_version.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <cstring>
#include <functional>

namespace stereoshift {

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

bool hasSpirvMagic(const std::string& bytes) {
  if (bytes.size() < 4) return false;
  uint32_t magic;
  std::memcpy(&magic, bytes.data(), 4);
  return magic == kSpirvMagic;
}

Stage stageFromModel(spv::ExecutionModel model) {
  switch (model) {
    case spv::ExecutionModelVertex: return Stage::Vertex;
    case spv::ExecutionModelTessellationControl: return Stage::TessControl;
    case spv::ExecutionModelTessellationEvaluation: return Stage::TessEvaluation;
    case spv::ExecutionModelGeometry: return Stage::Geometry;
    case spv::ExecutionModelFragment: return Stage::Fragment;
    case spv::ExecutionModelGLCompute: return Stage::Compute;
    case spv::ExecutionModelTaskEXT: case spv::ExecutionModelTaskNV: return Stage::Task;
    case spv::ExecutionModelMeshEXT: case spv::ExecutionModelMeshNV: return Stage::Mesh;
    case spv::ExecutionModelRayGenerationKHR: return Stage::RayGen;
    case spv::ExecutionModelIntersectionKHR: return Stage::Intersection;
    case spv::ExecutionModelAnyHitKHR: return Stage::AnyHit;
    case spv::ExecutionModelClosestHitKHR: return Stage::ClosestHit;
    case spv::ExecutionModelMissKHR: return Stage::Miss;
    case spv::ExecutionModelCallableKHR: return Stage::Callable;
    default: return Stage::Unknown;
  }
}

void recordLanguage(StageRecord& record, const SourceInfo& info) {
  record.languageDecided = true;
  record.language = info.language;
  record.languageSource = info.languageSource;
  record.languageReason = info.languageReason;
}

bool readSpirvInput(StagePlan& plan) {
  const std::string& bytes = plan.input->contents;
  if (bytes.size() % 4 != 0 || !hasSpirvMagic(bytes)) {
    plan.diags.error(plan.input->path, "not a SPIR-V binary: " + std::string(bytes.size() % 4 ? "size is not a multiple of 4 bytes"
                                                                                              : "bad magic number"));
    return false;
  }
  plan.spirvInput = true;
  plan.words.resize(bytes.size() / 4);
  std::memcpy(plan.words.data(), bytes.data(), bytes.size());
  plan.info.language = SourceLanguage::Spirv;
  plan.info.languageSource = LanguageSource::Content;
  plan.info.languageReason = "SPIR-V magic number";
  plan.info.vulkan = true;
  return true;
}

// The module in the IR, parsed once (a pipeline parses it early for its questions across stages).
Status parseModuleOnce(StagePlan& plan) {
  if (plan.module) return Done{};
  std::string error;
  plan.module = spirv::Module::parse(plan.words.empty() ? plan.front.spirv : plan.words, &error);
  if (!plan.module) return plainError(std::move(error));
  return Done{};
}

}  // namespace

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool isSpirvInput(const SourceFile& input) { return hasSpirvMagic(input.contents) || input.path.ends_with(".spv"); }

// Text with a NUL byte only inside a comment or at its end is still text (source/lexer.h).
bool isBinaryContent(const std::string& contents) {
  return contents.find('\0') != std::string::npos && !source::nulsOnlyInCommentsOrAtEnd(contents);
}

bool goesThroughFrontEnd(const SourceFile& input) {
  return !input.contents.empty() && !isSpirvInput(input) && !isBinaryContent(input.contents);
}

StageDecision decideInputStage(const SourceFile& input, const TranspileOptions& options) {
  return decideStage(input.path, input.contents, options.stage, options.stageExtensions);
}

// Whether a module declares any resource variable (uniform, push constant, storage buffer, image,
// sampler): a scan of its OpVariable instructions' storage classes.
bool declaresResources(const std::vector<uint32_t>& words) {
  for (size_t i = 5; i < words.size();) {
    uint32_t count = words[i] >> 16, opcode = words[i] & 0xffff;
    if (count == 0) break;
    if (opcode == spv::OpVariable && i + 3 < words.size()) {
      uint32_t storage = words[i + 3];
      if (storage == spv::StorageClassUniformConstant || storage == spv::StorageClassUniform ||
          storage == spv::StorageClassPushConstant || storage == spv::StorageClassStorageBuffer)
        return true;
    }
    i += count;
  }
  return false;
}

void runFrontEnd(StagePlan& plan, const TranspileOptions& options) {
  auto started = std::chrono::steady_clock::now();
  if (!plan.stage) plan.stage = decideInputStage(*plan.input, options);
  // 3Dmigoto's pixel shaders get their corrections in their own text, placed by source line.
  FrontEndOptions frontOptions = options;
  frontOptions.sourceLines = options.eyeFrom3DMigoto;
  plan.front = compileToSpirv(*plan.input, frontOptions, plan.diags, &*plan.stage);
  // An explicit --eye-source loose-uniforms asks for OpenGL's default-block uniforms: it says a
  // shader the source alone leaves open (desktop >= 400 / ES >= 310 with no resources of its own,
  // which glslang reads as Vulkan GLSL first) is OpenGL GLSL, as --target-env opengl does. A shader
  // with Vulkan resources (sets, push constants) stays Vulkan, and eye-params says why loose
  // uniforms cannot be had there.
  bool openGlAsked = options.eye.source == EyeSource::LooseUniforms && !options.targetEnv;
  if (openGlAsked && plan.front.ok && plan.front.info.vulkan && !declaresResources(plan.front.spirv)) {
    FrontEndOptions openGl = frontOptions;
    openGl.targetEnv = TargetEnv::OpenGL45;
    Diagnostics openGlDiags;
    FrontEndResult reparsed = compileToSpirv(*plan.input, openGl, openGlDiags, &*plan.stage);
    if (reparsed.ok) plan.front = std::move(reparsed);
  }
  plan.frontEndRan = true;
  plan.frontEndMs = msSince(started);
}

bool parseEarly(StagePlan& plan, const TranspileOptions& options) {
  if (!plan.front.ok) return false;
  if (!parseModuleOnce(plan)) return false;  // reported when the stage converts
  plan.analyses =
      std::make_unique<AnalysisManager>(*plan.module, plan.front.info, plan.input->path, !options.foldedCopyCrashed);
  return true;
}

namespace {

// The #version a loader prepends to this stage's text when it has none: the version the front end
// read it at, when it read it at all.
std::optional<std::string> versionIfNone(const StagePlan& plan) {
  if (!plan.front.ok || plan.front.info.language != SourceLanguage::Glsl) return std::nullopt;
  const SourceInfo& info = plan.front.info;
  return std::to_string(info.version) + (info.es && info.version != 100 ? " es" : "");
}

// The version text without #version is compiled at in Mesa: the one Mesa took the original at, else
// the front end's.
std::optional<std::string> mesaVersion(const StagePlan& plan) {
  if (plan.record.mesa && !plan.record.mesa->readAt.empty()) return plan.record.mesa->readAt;
  return versionIfNone(plan);
}


// Mesa's word on the output of a stage whose original Mesa compiled: it must compile too.
bool mesaAgreesOnOutput(StagePlan& plan, const std::string& output) {
  if (!plan.record.mesa || plan.record.mesa->original != "compiled") return true;
  const std::string& file = plan.input->path;
  const Stage stage = plan.stage && plan.stage->stage ? *plan.stage->stage : Stage::Unknown;
  MesaVerdict verdict = compileWithMesa(output, stage, file, mesaVersion(plan));
  if (verdict.kind == MesaVerdict::Kind::Compiled) {
    plan.record.mesa->output = "compiled";
    return true;
  }
  if (verdict.kind == MesaVerdict::Kind::Unavailable) {
    plan.record.mesa->output = "no verdict: " + verdict.why;
    return true;
  }
  plan.record.mesa->output = "refused";
  plan.diags.error(file, "the converted shader does not compile in Mesa (" + verdict.driver +
                             "), though the original does; no output was written");
  for (const auto& e : verdict.errors)
    plan.diags.note(file, "in the output, line " + std::to_string(e.line) + ":" + std::to_string(e.column) + ": " +
                              e.message);
  return false;
}

}  // namespace

// Mesa's word (frontend/mesa_compiler.h) on the original text of a GLSL stage that `route` would
// take where glslang did not say yes as written: true when the route may go on. Refused: the user
// sees Mesa's errors (the driver's word), glslang's go. No verdict: refused with what to install,
// unless --unchecked-text-route takes it anyway (said in a warning and the report).
// Mesa's verdict on the input's text, compiled once per stage whichever route asks first.
const MesaVerdict& originalVerdict(StagePlan& plan) {
  if (plan.originalMesaVerdict) return *plan.originalMesaVerdict;
  const Stage stage = plan.stage && plan.stage->stage ? *plan.stage->stage : Stage::Unknown;
  // Vulkan GLSL: glslang is its reference compiler, and OpenGL's cannot read it (descriptor sets,
  // push constants): there is no second word to be had.
  MesaVerdict& verdict = plan.originalMesaVerdict.emplace();
  if (isVulkanGlslText(plan.input->contents))
    verdict.why = "the shader is Vulkan GLSL, which only glslang, its reference compiler, reads; no OpenGL compiler can vouch for it";
  else
    verdict = compileWithMesa(plan.input->contents, stage, plan.input->path, versionIfNone(plan));
  return verdict;
}

bool mesaAgreesOnOriginal(StagePlan& plan, const TranspileOptions& options, const char* route) {
  const std::string& file = plan.input->path;
  const MesaVerdict& verdict = originalVerdict(plan);
  StageRecord::MesaCheck& check = plan.record.mesa.emplace();
  check.driver = verdict.driver;
  check.readAt = verdict.version;
  switch (verdict.kind) {
    case MesaVerdict::Kind::Compiled:
      check.original = "compiled";
      return true;
    case MesaVerdict::Kind::Refused: {
      check.original = "refused";
      Diagnostics kept;
      for (const auto& d : plan.diags.all())
        if (d.severity != Severity::Error) kept.add(d);
      for (auto& e : verdict.errors) kept.add(std::move(e));
      kept.note(file, std::string("glslang refuses this shader too; the ") + route +
                          " route is taken only where Mesa's GLSL compiler (" + verdict.driver + ") compiles it");
      plan.diags = std::move(kept);
      return false;
    }
    case MesaVerdict::Kind::Unavailable:
      break;
  }
  if (options.uncheckedTextRoute) {
    check.original = "unchecked: " + verdict.why;
    plan.diags.warning(file, "no GLSL compiler checked this shader, which glslang refuses (" + verdict.why + "): the " +
                                 route + " route is taken unchecked (--unchecked-text-route)");
    return true;
  }
  check.original = "no verdict: " + verdict.why;
  // An error where glslang's are not (the lifted copy parsed): the refusal must say why.
  const std::string why = std::string("the ") + route + " route is taken only where Mesa's GLSL compiler compiles the "
                          "shader, and none could be asked (" + verdict.why + "): install " + kMesaPackages +
                          " where Mesa is missing, or pass --unchecked-text-route to take it unchecked";
  if (plan.diags.hasErrors())
    plan.diags.note(file, why);
  else
    plan.diags.error(file, why);
  return false;
}

bool mesaCompilesOriginal(StagePlan& plan) {
  if (!plan.input || plan.front.info.language != SourceLanguage::Glsl) return false;
  return originalVerdict(plan).kind == MesaVerdict::Kind::Compiled;
}

bool checkOutputWithMesa(StagePlan& plan) {
  if (plan.binaryOutput || plan.front.info.language != SourceLanguage::Glsl || !plan.record.mesa) return true;
  if (plan.record.target && *plan.record.target != TargetLanguage::Glsl && *plan.record.target != TargetLanguage::Essl)
    return true;
  if (mesaAgreesOnOutput(plan, plan.output)) return true;
  plan.output.clear();
  return false;
}

bool readStage(StagePlan& plan, const TranspileOptions& options) {
  const SourceFile& input = *plan.input;
  const std::string& file = input.path;
  plan.record.file = file;
  if (input.contents.empty()) {
    plan.diags.error(file, "file is empty: no shader to convert");
    return false;
  }
  if (isSpirvInput(input)) {
    if (!readSpirvInput(plan)) return false;
  } else {
    if (isBinaryContent(input.contents)) {
      plan.diags.error(file, "binary content is not shader source (and not SPIR-V: bad magic number)");
      return false;
    }
    double earlier = plan.frontEndRan ? plan.frontEndMs : 0.0;  // a pipeline ran it before this stage's clock
    if (!plan.frontEndRan) {
      runFrontEnd(plan, options);
      earlier = 0.0;
    }
    if (!plan.front.ok) {
      recordLanguage(plan.record, plan.front.info);  // the language decision is often why it does not parse
      return false;
    }
    // A GLSL shader glslang took only as a lifted copy (glsl_lift.h): Mesa must compile it as written.
    if (plan.front.info.language == SourceLanguage::Glsl && !plan.front.info.liftedBecause.empty() &&
        !mesaAgreesOnOriginal(plan, options, "lifted-copy"))
      return false;
    plan.words = plan.front.spirv;
    plan.info = plan.front.info;
    plan.record.dialectReason = plan.front.dialectReason;
    plan.record.lifted = plan.front.info.liftedBecause;
    plan.includedFiles = plan.front.includedFiles;
    plan.record.includedFiles = plan.includedFiles;
    plan.record.frontEndMs = msSince(plan.started) + earlier;
    return true;
  }
  plan.record.frontEndMs = msSince(plan.started);
  return true;
}


bool parseStage(StagePlan& plan, const TranspileOptions& options) {
  const std::string& file = plan.input->path;
  if (Status parsed = parseModuleOnce(plan); !parsed) {
    plan.diags.add(located(parsed.error(), file));
    return false;
  }
  if (plan.spirvInput) {
    if (!validateSpirv(plan.words, plan.info, file, "input", plan.diags)) return false;
    plan.info.stage = stageFromModel(plan.module->executionModel());
    plan.info.entryPoint = plan.module->entryPointName();
    if (plan.module->entryPoints.empty()) {
      plan.diags.error(file, "SPIR-V module has no entry point");
      return false;
    }
  }
  StageRecord& record = plan.record;
  record.stage = plan.info.stage;
  record.stageReason = plan.spirvInput ? "the module's execution model" : plan.stage->reason;
  recordLanguage(record, plan.info);
  if (plan.info.language == SourceLanguage::Glsl)
    record.dialect = std::to_string(plan.info.version) + (plan.info.es ? " es" : "") + (plan.info.vulkan ? " vulkan" : "");
  if (!plan.analyses)
    plan.analyses = std::make_unique<AnalysisManager>(*plan.module, plan.info, file, !options.foldedCopyCrashed);
  return true;
}

void chooseStageOptions(StagePlan& plan, const TranspileOptions& options) {
  plan.options = options;
  // An OpenGL GLSL shader below the version its single-pass mode needs is re-emitted at that version
  // (a 330 vertex shader writing gl_Layer needs 410), said in a note and the report.
  std::string why;
  if (std::optional<int> raised = singlePassRaisedGlslVersion(plan.info, options, &why)) {
    plan.record.versionRaised = StageRecord::VersionRaise{plan.info.version, *raised, why};
    plan.diags.note(plan.input->path, "output raised from GLSL " + std::to_string(plan.info.version) + " to " +
                                          std::to_string(*raised) + ": " + why +
                                          " (desktop GLSL links stages of different versions)");
    plan.options.targetVersion = *raised;
  }
  // Legacy GLSL kept in its own dialect declares the eye parameters as loose uniforms (ESSL 100 and
  // GLSL below 140 have no uniform blocks).
  if (takesLegacyGlslRoute(plan.info, resolveTarget(plan.info, plan.options), plan.options) &&
      plan.options.eye.source == EyeSource::Auto)
    plan.options.eye.source = EyeSource::LooseUniforms;
  // An HLSL vertex shader spliced back into its text shifts every vertex entry point of the file:
  // each is planned here, converted when the splice needs it.
  if (plan.info.stage == Stage::Vertex && takesHlslSpliceRoute(plan.info, resolveTarget(plan.info, plan.options)))
    for (const HlslEntryPoint& other : findHlslEntryPoints(plan.input->contents))
      if (other.name != plan.info.entryPoint) plan.otherEntries.push_back({other.name, other.stage, other.foundBy});
}

// --corrections-only on a pre-rasterization stage: its position is the driver's; what is left to
// write is the halo copies of it, which the HLSL vertex splice shifts alone (the position returned
// as it is). Anything else of the stage (the eye parameters declared for the copies, outputs only
// derived from the position, other dialects and stages, whose splices shift the position with its
// copies) is dropped: the stage is written as it was, and a derived output is said in a warning.
void keepOnlyCorrections(StagePlan& plan, PassContext& ctx) {
  if (ctx.classification != Classification::Perspective || !plan.changed) return;
  const HaloFacts& halo = ctx.record.halo;
  const bool haloEdited = ctx.record.madeEdit(EditKind::DerivedOutputShift);
  bool copies = haloEdited && halo.derivedOutputs.empty();
  bool hlslVertex = plan.info.language == SourceLanguage::Hlsl && plan.info.stage == Stage::Vertex &&
                    resolveTarget(plan.info, plan.options) == TargetLanguage::Hlsl;
  if (copies && hlslVertex) return;
  if (haloEdited) {
    std::string first = !halo.derivedOutputs.empty()                           ? halo.derivedOutputs.front()
                        : halo.shiftedOutputs && !halo.shiftedOutputs->empty() ? halo.shiftedOutputs->front()
                        : !halo.movedLanes.empty()                              ? halo.movedLanes.front().output
                                                                                : std::string("?");
    plan.diags.warning(plan.input->path, "--corrections-only: the outputs derived from the clip position (" + first +
                                             ") are not shifted: only an HLSL vertex shader's exact copies of it, and "
                                             "lanes linear in its x, are");
  }
  plan.changed = false;
}

bool runStagePasses(StagePlan& plan) {
  auto started = std::chrono::steady_clock::now();
  plan.context = std::make_unique<PassContext>(*plan.module, plan.options, plan.info, plan.diags, plan.input->path,
                                               *plan.analyses);
  PassContext& ctx = *plan.context;
  ctx.nextStage = plan.nextStage ? &*plan.nextStage : nullptr;
  if (!plan.spirvInput) ctx.frontEndSpirv = &plan.words;
  ctx.output = {plan.options.target, plan.options.targetVersion};
  decideOutputCapability(plan.info, resolveTarget(plan.info, plan.options), ctx.output);
  plan.record.passesRan = true;
  bool ok = runPassPipeline(ctx, &plan.changed, &plan.passLog);
  if (ok && plan.options.correctionsOnly) keepOnlyCorrections(plan, ctx);
  plan.record.passes = ctx.record;
  if (!ok) return false;
  plan.record.classification = ctx.classification;
  plan.record.changed = plan.changed;
  plan.record.passesMs = msSince(started);
  plan.record.target = resolveTarget(plan.info, plan.options);
  return true;
}

namespace {

// The other vertex entry points of an HLSL file, each through its own front end and passes (a 2D
// one gets no shift). Their diagnostics stay with them: the splice route says what a failure means.
void convertOtherEntryPoints(StagePlan& plan) {
  if (!plan.options.entryPoint.empty()) return;  // -e NAME shifts only NAME
  for (OtherEntryPoint& other : plan.otherEntries) {
    if (other.stage != Stage::Vertex || other.converted) continue;
    other.converted = true;
    auto entry = std::make_unique<StagePlan>();
    entry->input = plan.input;
    entry->options = plan.options;
    entry->options.entryPoint = other.name;
    entry->options.stage = Stage::Vertex;
    FrontEndResult front = compileToSpirv(*plan.input, entry->options, other.diags);
    if (!front.ok) continue;
    std::string error;
    entry->module = spirv::Module::parse(front.spirv, &error);
    if (!entry->module) {
      other.diags.error(plan.input->path, "entry point '" + other.name + "': " + error);
      continue;
    }
    entry->info = front.info;
    entry->analyses = std::make_unique<AnalysisManager>(*entry->module, entry->info, plan.input->path,
                                                        !entry->options.foldedCopyCrashed);
    entry->context = std::make_unique<PassContext>(*entry->module, entry->options, entry->info, other.diags,
                                                   plan.input->path, *entry->analyses);
    std::string log;
    if (!runPassPipeline(*entry->context, &other.changed, &log)) continue;
    other.ok = true;
    other.context = entry->context.get();
    plan.entryPlans.push_back(std::move(entry));
  }
}

// One re-compile a route asked for (route.h, CompileCheck).
// `mesaDecides`: asked where glslang does not take GLSL output: true when Mesa's GLSL compiler
// compiles both the original and the output (glslang's refusal is then its own gap, as with the
// original), which it says in a note.
bool runCompileCheck(const CompileCheck& check, const TranspileOptions& options, const std::string& file,
                     Diagnostics& diags, const std::function<bool(const CompileCheck&)>& mesaDecides) {
  Diagnostics verifyDiags;
  std::string display = file + " (emitted)";
  if (check.throughFrontEnd) {
    StageDecision stage;
    stage.stage = check.stage;
    stage.reason = "the input's stage";
    FrontEndResult again = compileToSpirv(SourceFile{file, check.text}, options, verifyDiags, &stage);
    if (again.ok) return true;
    diags.append(verifyDiags);
    diags.error(file, check.failure);
    return false;
  }
  bool ok = check.legacy ? verifyLegacyCompiles(check.text, check.stage, check.version, check.es, display, verifyDiags)
                         : verifyCompiles(check.blankEffects ? hlslForGlslang(check.text) : check.text, check.language,
                                          check.stage, check.entryPoint, check.vulkanSemantics, display, verifyDiags,
                                          &options, check.includeFrom);
  if (ok) return true;
  if (mesaDecides && check.language == SourceLanguage::Glsl && mesaDecides(check)) {
    const auto& all = verifyDiags.all();
    auto first = std::find_if(all.begin(), all.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
    diags.note(file, "glslang does not take the output (" + (first == all.end() ? check.failure : first->message) +
                         "), nor the original as written; Mesa's GLSL compiler compiles both");
    return true;
  }
  diags.append(verifyDiags);
  diags.error(file, check.failure);
  return false;
}

// The first of a route's checks that fails, as its first error ("" when all pass). Its errors go to
// `diags` unless the route declines on a failed check.
std::string failedCheck(const EmitResult& emitted, const TranspileOptions& options, const std::string& file,
                        Diagnostics& diags, const std::function<bool(const CompileCheck&)>& mesaDecides) {
  for (const auto& check : emitted.checks) {
    Diagnostics checkDiags;
    if (runCompileCheck(check, options, file, checkDiags, mesaDecides)) {
      diags.append(checkDiags);  // a note where Mesa's word decided
      continue;
    }
    if (!emitted.declineIfChecksFail) diags.append(checkDiags);
    return checkDiags.hasErrors() ? checkDiags.all().front().message : check.failure;
  }
  return {};
}

// The module must validate before any route writes it; a module the front end already made invalid
// (an OpenGL loose `uniform bool`) is recorded, and the SPIR-V routes refuse it.
bool validateForRoutes(StagePlan& plan, EmitRequest& request) {
  request.finalWords = plan.module->encode();
  std::string inherited;
  if (!validateSpirv(request.finalWords, plan.info, plan.input->path, "after the passes", plan.diags,
                     plan.context->frontEndSpirv, &inherited))
    return false;
  request.inheritedInvalid = inherited;
  plan.record.frontEndSpirvInvalid = inherited;
  // --target-env vulkan1.0 asked for explicitly: HLSL's cbuffer packing needs the relaxed block
  // layout Vulkan 1.0 has only as an extension.
  TargetLanguage target = *plan.record.target;
  if ((target == TargetLanguage::Spirv || target == TargetLanguage::SpirvAsm) &&
      plan.options.targetEnv == TargetEnv::Vulkan1_0) {
    if (std::string strict = vulkan10StrictLayoutErrors(request.finalWords); !strict.empty()) {
      plan.diags.error(plan.input->path,
                       "--target-env vulkan1.0: the SPIR-V needs the relaxed block layout (VK_KHR_relaxed_block_layout, "
                       "core from Vulkan 1.1) for its buffers as HLSL packs them (" +
                           strict.substr(0, strict.find('\n')) + "); use --target-env vulkan1.1 or later");
      return false;
    }
  }
  return true;
}

void noteDecline(StagePlan& plan, const std::string& note) {
  plan.record.emit.notes.push_back(note);
  plan.diags.note(plan.input->path, note);
}

}  // namespace

// SPIR-V for a Vulkan environment from OpenGL GLSL: glslang makes OpenGL's SPIR-V of it (uniforms
// outside a block, no descriptor sets), which a Vulkan validator and driver refuse. Refused with
// the reason rather than written under the environment the user asked for.
bool checkVulkanEnvironment(StagePlan& plan) {
  const auto& env = plan.options.targetEnv;
  TargetLanguage target = *plan.record.target;
  bool spirv = target == TargetLanguage::Spirv || target == TargetLanguage::SpirvAsm;
  if (!spirv || !env || *env == TargetEnv::OpenGL45 || plan.info.vulkan || plan.info.language != SourceLanguage::Glsl)
    return true;
  plan.diags.error(plan.input->path,
                   "--target-env " + std::string(targetEnvName(*env)) +
                       ": this is OpenGL GLSL (glslang takes it only under OpenGL's rules), whose SPIR-V is OpenGL's "
                       "and does not validate for Vulkan; use --target-env opengl, or give "
                       "the shader Vulkan GLSL's interface (uniforms in blocks with set and binding, locations on every "
                       "input and output)");
  return false;
}

bool emitStage(StagePlan& plan) {
  const std::string& file = plan.input->path;
  if (!checkVulkanEnvironment(plan)) return false;
  EmitRequest request{*plan.input, *plan.context, plan.options, *plan.record.target, plan.changed};
  request.entryPointOption = plan.options.entryPoint;
  bool validated = false;
  auto backStarted = std::chrono::steady_clock::now();
  for (const auto& route : routes()) {
    if (route->needsValidModule() && !validated) {
      if (!validateForRoutes(plan, request)) return false;
      validated = true;
      backStarted = std::chrono::steady_clock::now();
    }
    RouteDecision decision = route->accepts(request);
    if (decision.kind == RouteDecision::Decline) {
      if (decision.noted) noteDecline(plan, decision.why);
      continue;
    }
    if (decision.kind == RouteDecision::Refuse) {
      plan.diags.error(file, decision.why);
      return false;
    }
    // 3Dmigoto's StereoParams texture is rendered by the HLSL splice alone; a stage that needs
    // another route to change it cannot take its eye parameters from there (a copy changes nothing).
    if (plan.options.eyeFrom3DMigoto && !route->takesStereoParamsTexture()) {
      plan.diags.error(file, std::string("--eye-source 3dmigoto: the eye parameters are 3Dmigoto's StereoParams texture, "
                                         "which only the HLSL source splice writes; this stage takes the ") +
                                 route->name() + " route" +
                                 (plan.record.emit.notes.empty() ? "" : " (" + plan.record.emit.notes.back() + ")"));
      return false;
    }
    if (route->needsOtherEntryPoints() && plan.info.stage == Stage::Vertex) {
      convertOtherEntryPoints(plan);
      request.otherEntries = &plan.otherEntries;
    }
    EmitFacts before = plan.record.emit;
    EmitResult emitted = route->emit(request, plan.record.emit, plan.diags);
    if (emitted.status == EmitResult::Declined) {
      plan.record.emit = std::move(before);
      noteDecline(plan, emitted.declinedBecause);
      continue;
    }
    if (emitted.status == EmitResult::Failed) return false;
    // GLSL output glslang does not take, where it does not take the original as written either (the
    // check at the original's version): Mesa's word on both decides, recorded in the report.
    auto mesaDecides = [&](const CompileCheck& check) {
      if (plan.front.info.language != SourceLanguage::Glsl || plan.spirvInput) return false;
      if (!plan.record.mesa) {
        CompileCheck original = check;
        original.text = plan.input->contents;
        Diagnostics ignored;
        if (runCompileCheck(original, plan.options, file, ignored, nullptr)) return false;  // glslang's word stands
        MesaVerdict verdict = compileWithMesa(plan.input->contents, check.stage, file, versionIfNone(plan));
        if (verdict.kind != MesaVerdict::Kind::Compiled) return false;
        plan.record.mesa = StageRecord::MesaCheck{"compiled", "", verdict.driver, verdict.version};
      }
      if (plan.record.mesa->original != "compiled") return false;
      MesaVerdict output = compileWithMesa(check.text, check.stage, file, mesaVersion(plan));
      if (output.kind != MesaVerdict::Kind::Compiled) return false;
      plan.record.mesa->output = "compiled";
      return true;
    };
    if (std::string failed = failedCheck(emitted, plan.options, file, plan.diags, mesaDecides); !failed.empty()) {
      if (!emitted.declineIfChecksFail) return false;
      plan.record.emit = std::move(before);
      noteDecline(plan, std::string(route->name()) + ": its text does not compile (" + failed + "); the next route writes the stage");
      continue;
    }
    plan.record.verified = emitted.reportsVerified;
    plan.output = std::move(emitted.output);
    plan.binaryOutput = emitted.binary;
    plan.copied = emitted.copied;
    if (plan.copied) {
      plan.record.output = StageRecord::Output::Copied;
    } else {
      plan.record.backEndMs = msSince(backStarted);
      plan.record.output = StageRecord::Output::Emitted;
    }
    plan.record.totalMs = msSince(plan.started);
    return true;
  }
  plan.diags.error(file, "internal error: no back-end route takes this stage");
  return false;
}

}  // namespace stereoshift
