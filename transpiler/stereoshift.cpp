#include "transpiler/stereoshift.h"

#include "transpiler/backend/back_end.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/language_detect.h"
#include "transpiler/backend/emit_prep.h"
#include "transpiler/backend/splice_route.h"
#include "transpiler/backend/glsl_splice.h"
#include "transpiler/frontend/legacy_glsl.h"
#include "transpiler/hlsl_file_splice.h"
#include "passes/ir/validate.h"
#include "passes/pass_manager.h"
#include "passes/ir/module.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <cstring>

namespace stereoshift {

const char* version() { return STEREOSHIFT_VERSION; }

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

const char* languageName(SourceLanguage l) {
  switch (l) {
    case SourceLanguage::Glsl: return "glsl";
    case SourceLanguage::Hlsl: return "hlsl";
    case SourceLanguage::Spirv: return "spirv";
  }
  return "?";
}

const char* targetName(TargetLanguage t) {
  switch (t) {
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

bool isSpirvBinary(const std::string& bytes) {
  if (bytes.size() < 4) return false;
  uint32_t magic;
  std::memcpy(&magic, bytes.data(), 4);
  return magic == kSpirvMagic;
}

std::string bytesOf(const std::vector<uint32_t>& words) {
  std::string out(words.size() * 4, '\0');
  std::memcpy(out.data(), words.data(), out.size());
  return out;
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string defaultOutputExtension(const SourceFile& input, const TranspileOptions& options) {
  switch (options.target) {
    case TargetLanguage::Spirv: return ".spv";
    case TargetLanguage::SpirvAsm: return ".spvasm";
    case TargetLanguage::Msl: return ".metal";
    case TargetLanguage::Hlsl: return ".hlsl";
    default: break;
  }
  auto dot = input.path.find_last_of('.');
  return dot == std::string::npos ? std::string() : input.path.substr(dot);
}

namespace {

// The front end's result for one stage, kept so a pipeline parses each stage once.
struct CompiledStage {
  FrontEndResult front;
  Diagnostics diags;
  double ms = 0;  // front-end time, reported with the stage
  // The folded copy an analysis of the untouched module already made (see foldedCopy()), handed
  // on so the stage's own passes do not run the optimizer a second time.
  std::optional<spirv::Module> folded;
  bool foldTried = false;
  // The front end's module in the IR, parsed once for the pipeline-wide analyses and the stage's own
  // conversion (see parsedModule()).
  std::optional<spirv::Module> module;
};

// The stage's module, parsed on first use; null when the front end failed or the SPIR-V does not
// parse (the stage's conversion then says why).
spirv::Module* parsedModule(CompiledStage& stage) {
  if (!stage.front.ok) return nullptr;
  if (!stage.module) {
    std::string error;
    stage.module = spirv::Module::parse(stage.front.spirv, &error);
  }
  return stage.module ? &*stage.module : nullptr;
}

// One shader; `nextStage` (pipelines only) tells per-eye-view how the fragment stage uses the
// outputs of the last pre-rasterization stage. `compiled`: the stage already through the front end
// (pipelines), or null to run it here.
TranspileResult transpileStage(const SourceFile& input, const TranspileOptions& requestedOptions,
                               const NextStageFacts* nextStage, CompiledStage* compiled = nullptr) {
  auto started = std::chrono::steady_clock::now();
  // The options as requested, but for an output version a single-pass mode raises (below).
  TranspileOptions effectiveOptions = requestedOptions;
  const TranspileOptions& options = effectiveOptions;
  TranspileResult result;
  Diagnostics& diags = result.diagnostics;
  const std::string& file = input.path;
  result.report["file"] = file;

  if (input.contents.empty()) {
    diags.error(file, "file is empty: no shader to convert");
    return result;
  }

  // ---- front end ----
  SourceInfo info;
  std::vector<uint32_t> words;
  if (isSpirvBinary(input.contents) || file.ends_with(".spv")) {
    if (input.contents.size() % 4 != 0 || !isSpirvBinary(input.contents)) {
      diags.error(file, "not a SPIR-V binary: " + std::string(input.contents.size() % 4 ? "size is not a multiple of 4 bytes" : "bad magic number"));
      return result;
    }
    words.resize(input.contents.size() / 4);
    std::memcpy(words.data(), input.contents.data(), input.contents.size());
    info.language = SourceLanguage::Spirv;
    info.languageSource = LanguageSource::Content;
    info.languageReason = "SPIR-V magic number";
    info.vulkan = true;
  } else {
    if (std::memchr(input.contents.data(), '\0', std::min<size_t>(input.contents.size(), 4096))) {
      diags.error(file, "binary content is not shader source (and not SPIR-V: bad magic number)");
      return result;
    }
    FrontEndResult front;
    if (compiled) {
      front = std::move(compiled->front);
      diags.append(compiled->diags);
    } else {
      front = compileToSpirv(input, options, diags);
    }
    if (!front.ok) {
      // The language decision is reported even when the shader does not parse: it is often why.
      result.report["language"] = languageName(front.info.language);
      result.report["language_source"] = languageSourceName(front.info.languageSource);
      result.report["language_reason"] = front.info.languageReason;
      return result;
    }
    words = std::move(front.spirv);
    info = std::move(front.info);
    if (!front.dialectReason.empty()) result.report["dialect_reason"] = front.dialectReason;
    result.includedFiles = std::move(front.includedFiles);
    if (!result.includedFiles.empty()) result.report["included_files"] = result.includedFiles;
  }
  result.report["timings_ms"]["front_end"] = msSince(started) + (compiled ? compiled->ms : 0.0);

  result.originalSpirv = words;
  std::string parseError;
  auto parsed = compiled && compiled->module ? std::move(compiled->module) : spirv::Module::parse(words, &parseError);
  if (!parsed) {
    diags.error(file, parseError);
    return result;
  }
  spirv::Module module = std::move(*parsed);
  if (info.language == SourceLanguage::Spirv) {
    if (!validateSpirv(words, info, file, "input", diags)) return result;
    info.stage = stageFromModel(module.executionModel());
    info.entryPoint = module.entryPointName();
    if (module.entryPoints.empty()) {
      diags.error(file, "SPIR-V module has no entry point");
      return result;
    }
  }
  result.report["stage"] = stageName(info.stage);
  result.report["stage_reason"] = info.language == SourceLanguage::Spirv
                                      ? "the module's execution model"
                                      : decideStage(input.path, input.contents, options.stage, options.stageExtensions).reason;
  result.report["language"] = languageName(info.language);
  result.report["language_source"] = languageSourceName(info.languageSource);
  result.report["language_reason"] = info.languageReason;
  if (info.language == SourceLanguage::Glsl)
    result.report["dialect"] = std::to_string(info.version) + (info.es ? " es" : "") + (info.vulkan ? " vulkan" : "");

  // An OpenGL GLSL shader below the version its single-pass mode needs is re-emitted at that version
  // (a 330 vertex shader writing gl_Layer needs 410), said in a note and the report.
  std::string raiseReason;
  if (std::optional<int> raised = singlePassRaisedGlslVersion(info, options, &raiseReason)) {
    result.report["version_raised"] = {{"from", info.version}, {"to", *raised}, {"why", raiseReason}};
    diags.note(file, "output raised from GLSL " + std::to_string(info.version) + " to " + std::to_string(*raised) +
                         ": " + raiseReason + " (desktop GLSL links stages of different versions)");
    effectiveOptions.targetVersion = *raised;
  }

  // ---- passes ----
  auto passesStarted = std::chrono::steady_clock::now();
  // Legacy GLSL kept in its own dialect declares the eye parameters as loose uniforms (ESSL 100 and
  // GLSL below 140 have no uniform blocks).
  TranspileOptions legacyOptions;
  bool legacyRoute = takesLegacyGlslRoute(info, resolveTarget(info, options), options);
  if (legacyRoute && options.eye.source == EyeSource::Auto) {
    legacyOptions = options;
    legacyOptions.eye.source = EyeSource::LooseUniforms;
  }
  PassContext ctx{module, legacyRoute && options.eye.source == EyeSource::Auto ? legacyOptions : options, info, diags,
                  file, result.report};
  ctx.nextStage = nextStage;
  if (info.language != SourceLanguage::Spirv) ctx.frontEndSpirv = &result.originalSpirv;
  if (compiled && compiled->foldTried) {
    ctx.folded = std::move(compiled->folded);
    ctx.foldTried = true;
  }
  bool changed = false;
  if (!runPassPipeline(ctx, &changed, &result.passLog)) return result;
  result.changed = changed;
  result.report["classification"] = toString(ctx.classification);
  result.report["changed"] = changed;
  result.report["timings_ms"]["passes"] = msSince(passesStarted);

  TargetLanguage target = resolveTarget(info, options);
  result.report["target"] = targetName(target);
  bool sameLanguage = (info.language == SourceLanguage::Spirv && target == TargetLanguage::Spirv) ||
                      (info.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl) ||
                      (info.language == SourceLanguage::Glsl &&
                       target == (info.es ? TargetLanguage::Essl : TargetLanguage::Glsl) && !options.targetVersion);
  // Nothing to inject: the input is already its own drop-in replacement, byte for byte.
  if (!changed && sameLanguage && !options.forceReemit) {
    result.output = input.contents;
    result.binaryOutput = info.language == SourceLanguage::Spirv;
    result.copiedThrough = true;
    result.ok = true;
    result.report["output"] = "copied";
    result.report["timings_ms"]["total"] = msSince(started);
    return result;
  }

  std::vector<uint32_t> finalWords = module.encode();
  std::string inherited;
  if (!validateSpirv(finalWords, info, file, "after the passes", diags, ctx.frontEndSpirv, &inherited)) return result;
  if (!inherited.empty()) {
    // e.g. a loose `uniform bool` of OpenGL GLSL: fine in the GLSL/HLSL/MSL SPIRV-Cross writes, not as SPIR-V.
    result.report["front_end_spirv_invalid"] = inherited;
    if (target == TargetLanguage::Spirv || target == TargetLanguage::SpirvAsm) {
      diags.error(file, "glslang's SPIR-V for this shader does not validate (" + inherited +
                            "); it cannot be written as SPIR-V (choose a source-language --target)");
      return result;
    }
  }

  // ---- back end ----
  auto backStarted = std::chrono::steady_clock::now();
  if (target == TargetLanguage::Spirv) {
    result.output = bytesOf(finalWords);
    result.binaryOutput = true;
  } else if (target == TargetLanguage::SpirvAsm) {
    result.output = spirv::disassemble(finalWords);
  } else if (HlslSpliceOutcome spliced = spliceHlslFile(input, ctx, target, result.output, result.report, diags);
             spliced != HlslSpliceOutcome::NotTaken) {
    // HLSL back to HLSL: the shift spliced into the original text, every entry point kept (the
    // passes above still classified it and chose the register); see hlsl_file_splice.h.
    if (spliced == HlslSpliceOutcome::Failed) return result;
  } else if (legacyRoute) {
    // ESSL 100 / GLSL 110-150 vertex shaders: the shift spliced into the original text (glsl_splice.h),
    // always re-compiled at the original version; an output that does not compile is never written.
    if (!spliceLegacyGlsl(input, ctx, result.output, result.report, diags)) return result;
    Diagnostics verifyDiags;
    if (!verifyLegacyCompiles(result.output, info.stage, info.version, info.es, file + " (emitted)", verifyDiags)) {
      diags.append(verifyDiags);
      diags.error(file, "the emitted shader does not compile at its original version");
      result.output.clear();
      return result;
    }
    result.report["verified"] = true;
  } else {
    spirv::Module emitModule = module;
    SourceInfo emitInfo = info;
    if (options.eye.glBinding && ctx.eye.variable) emitInfo.explicitBinding.insert(module.name(ctx.eye.variable));
    stripAutoAssignedQualifiers(emitModule, emitInfo);
    EmitHints hints = collectHints(emitModule);
    EmitResult emitted = emitSource(emitModule.encode(), info, options, hints, file, diags);
    if (!emitted.ok) return result;
    result.output = std::move(emitted.text);
    // Every GLSL/ESSL/HLSL text SPIRV-Cross writes is compiled again before it is written (not only
    // under --verify): a target that cannot express the shader (a Vulkan construct at an OpenGL version,
    // a built-in a dialect lacks) is refused with glslang's reason instead of becoming a file that does
    // not compile. MSL has no compiler here (see README "Not supported").
    if (target != TargetLanguage::Msl) {
      SourceLanguage lang = target == TargetLanguage::Hlsl ? SourceLanguage::Hlsl : SourceLanguage::Glsl;
      Diagnostics verifyDiags;
      std::string entry = target == TargetLanguage::Hlsl ? (info.entryPoint.empty() ? "main" : info.entryPoint) : "main";
      if (!verifyCompiles(result.output, lang, info.stage, entry, emitted.vulkanSemantics,
                          file + " (emitted)", verifyDiags, &options)) {
        diags.append(verifyDiags);
        diags.error(file, "the emitted " + std::string(targetName(target)) +
                              " does not compile; nothing was written (the target cannot express this shader as it is)");
        return result;
      }
      result.report["verified"] = true;
    }
  }
  result.report["timings_ms"]["back_end"] = msSince(backStarted);
  result.report["timings_ms"]["total"] = msSince(started);
  result.report["output"] = "emitted";
  result.ok = true;
  return result;
}

// How the fragment stage of a pipeline uses its inputs (for per-eye-view): analysed before the
// last pre-rasterization stage is converted. Null when there is no fragment stage to read.
std::optional<NextStageFacts> fragmentStageFacts(const std::vector<SourceFile>& stages,
                                                 std::vector<std::optional<CompiledStage>>& compiled,
                                                 const TranspileOptions& options, int last) {
  if (!options.perEyeView || last < 0) return std::nullopt;  // no stage to hand them to
  // The facts serve per-eye-view in the last pre-rasterization stage, which looks no further when that
  // stage has no vector subtraction: then the fragment stage's folded copy (an optimizer run, most of
  // a typical fragment shader's cost) is not worth making for them.
  // (Any pre-rasterization stage: a geometry or tessellation stage may pass the view vector on.)
  {
    bool matter = false;
    for (size_t i = 0; i < stages.size(); ++i) {
      auto kind = decideStage(stages[i].path, stages[i].contents, options.stage, options.stageExtensions).stage;
      if (kind == Stage::Fragment || kind == Stage::Compute) continue;
      const spirv::Module* module = compiled[i] ? parsedModule(*compiled[i]) : nullptr;
      matter |= !module || nextStageFactsMatter(*module, options);
    }
    if (!matter) return std::nullopt;
  }
  for (size_t i = 0; i < stages.size(); ++i) {
    auto kind = decideStage(stages[i].path, stages[i].contents, options.stage, options.stageExtensions).stage;
    if (kind != Stage::Fragment) continue;
    spirv::Module* module = compiled[i] ? parsedModule(*compiled[i]) : nullptr;
    if (!module) return std::nullopt;  // reported when the stage converts
    const FrontEndResult& front = compiled[i]->front;
    nlohmann::json scratch;
    Diagnostics ignored;
    PassContext ctx{*module, options, front.info, ignored, stages[i].path, scratch};
    NextStageFacts facts = analyseNextStage(ctx);
    compiled[i]->folded = std::move(ctx.folded);
    compiled[i]->foldTried = ctx.foldTried;
    return facts;
  }
  return std::nullopt;
}

}  // namespace

TranspileResult transpile(const SourceFile& input, const TranspileOptions& options) {
  return transpileStage(input, options, nullptr);
}

std::vector<TranspileResult> transpilePipeline(const std::vector<SourceFile>& stages, const TranspileOptions& options) {
  // The last pre-rasterization stage (vertex, tessellation evaluation, geometry or mesh) gets the shift.
  auto rank = [](Stage s) {
    switch (s) {
      case Stage::Vertex: return 1;
      case Stage::TessEvaluation: return 2;
      case Stage::Geometry: return 3;
      case Stage::Mesh: return 4;
      default: return 0;  // tessellation control, fragment, compute, task: never shifted
    }
  };
  int last = -1, lastRank = 0;
  for (size_t i = 0; i < stages.size(); ++i) {
    auto stage = decideStage(stages[i].path, stages[i].contents, options.stage, options.stageExtensions).stage;
    if (stage && rank(*stage) > lastRank) {
      last = static_cast<int>(i);
      lastRank = rank(*stage);
    }
  }
  // Each source stage goes through the front end once; the analyses below and the conversion share it.
  // Empty when the stage does not go through it (SPIR-V, unreadable input: transpileStage says why).
  std::vector<std::optional<CompiledStage>> compiled(stages.size());
  for (size_t i = 0; i < stages.size(); ++i) {
    const SourceFile& stage = stages[i];
    if (stage.contents.empty() || isSpirvBinary(stage.contents) || stage.path.ends_with(".spv") ||
        std::memchr(stage.contents.data(), '\0', std::min<size_t>(stage.contents.size(), 4096)))
      continue;
    auto frontStarted = std::chrono::steady_clock::now();
    compiled[i].emplace();
    compiled[i]->front = compileToSpirv(stage, options, compiled[i]->diags);
    compiled[i]->ms = msSince(frontStarted);
  }
  // The injected block must not take a binding another stage of the pipeline uses.
  TranspileOptions pipelineOptions = options;
  if (stages.size() > 1 && !options.eye.binding && !options.eye.hlslRegister) {
    std::optional<uint32_t> highest;
    bool hlsl = false;
    for (auto& c : compiled) {
      const spirv::Module* m = c ? parsedModule(*c) : nullptr;
      if (!m) continue;
      const FrontEndResult& front = c->front;
      hlsl |= front.info.language == SourceLanguage::Hlsl;
      auto stageHighest = highestBinding(*m, options.eye.descriptorSet.value_or(0), perClassRegisters(front.info));
      if (stageHighest) highest = std::max(highest.value_or(0), *stageHighest);
    }
    if (highest) {
      if (hlsl) pipelineOptions.eye.hlslRegister = *highest + 1;
      else pipelineOptions.eye.binding = *highest + 1;
    }
  }
  std::optional<NextStageFacts> fragmentFacts = fragmentStageFacts(stages, compiled, options, last);
  // The last pre-rasterization stage gets the fragment stage's facts; a stage before it gets them
  // carried back through the stages between (a geometry stage passing TangentViewPos on).
  std::vector<std::optional<NextStageFacts>> stageFacts(stages.size());
  if (fragmentFacts) {
    stageFacts[static_cast<size_t>(last)] = std::move(fragmentFacts);
    auto order = [&](size_t i) {  // pipeline order of the pre-rasterization stages, -1 for the others
      auto stage = decideStage(stages[i].path, stages[i].contents, options.stage, options.stageExtensions).stage;
      if (!stage) return -1;
      switch (*stage) {
        case Stage::Vertex: return 0;
        case Stage::TessControl: return 1;
        case Stage::TessEvaluation: return 2;
        case Stage::Geometry: return 3;
        default: return -1;
      }
    };
    for (size_t after = static_cast<size_t>(last);;) {
      std::optional<size_t> before;
      for (size_t i = 0; i < stages.size(); ++i)
        if (order(i) >= 0 && order(i) < order(after) && (!before || order(i) > order(*before))) before = i;
      spirv::Module* module = compiled[after] ? parsedModule(*compiled[after]) : nullptr;
      if (!before || !module) break;
      nlohmann::json scratch;
      Diagnostics ignored;
      PassContext ctx{*module, options, compiled[after]->front.info, ignored, stages[after].path, scratch};
      ctx.nextStage = &*stageFacts[after];
      stageFacts[*before] = carryNextStageFacts(ctx);
      compiled[after]->folded = std::move(ctx.folded);  // the stage's own passes reuse it
      compiled[after]->foldTried = ctx.foldTried;
      after = *before;
    }
  }
  std::vector<TranspileResult> results;
  for (size_t i = 0; i < stages.size(); ++i) {
    TranspileOptions stageOptions = pipelineOptions;
    stageOptions.shiftThisStage = static_cast<int>(i) == last;
    const NextStageFacts* facts = stageFacts[i] ? &*stageFacts[i] : nullptr;
    results.push_back(transpileStage(stages[i], stageOptions, facts, compiled[i] ? &*compiled[i] : nullptr));
  }
  return results;
}

}  // namespace stereoshift
