// verify's compile step: the pre-rasterization stages of the given sources, in pipeline order,
// each compiled to SPIR-V twice — the original as the front end makes it, and through
// stereoshift's passes (only the last stage shifted) — with what the comparison must know about
// each: which outputs may differ between the eyes, and whether its bindings are per-class
// namespaces (D3D registers, OpenGL's binding points).
#include "transpiler/verify/stereo_verify.h"

#include "transpiler/verify/harness_rewrites.h"
#include "passes/ir/module.h"
#include "passes/pass.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <string_view>

namespace stereoshift::harness {

namespace {

// The outputs the conversion computes differently per eye by design: those the halo pass
// re-derived from the shifted position, and those computed from the per-eye camera (per-eye-view:
// relief view vectors). The comparison lets them move between the eyes; eyeSign = 0 still has to
// be bit for bit.
std::vector<std::string> outputsExpectedToDiffer(const TranspileResult& result) {
  const RunRecord& passes = result.record.passes;
  std::vector<std::string> outputs = passes.halo.shiftedOutputs.value_or(std::vector<std::string>{});
  outputs.insert(outputs.end(), passes.perEyeView.perEyeOutputs.begin(), passes.perEyeView.perEyeOutputs.end());
  return outputs;
}

// Whether the stage's bindings are per-class namespaces, which the harness moves apart before
// binding: D3D registers (b, t, s, u) by the front end's rule (HLSL not written for Vulkan with
// [[vk::binding]]; SourceInfo::vulkanBindings), OpenGL's (texture units, uniform blocks, storage
// blocks, images, atomic counters) for GLSL not written for Vulkan.
BindingClasses bindingClassesOf(const TranspileResult& result) {
  if (perClassRegisters(result.source)) return BindingClasses::D3dRegisters;
  if (result.source.language == SourceLanguage::Glsl && !result.source.vulkan) return BindingClasses::OpenGL;
  return BindingClasses::Shared;
}

// Whether GLSL text says it was written for Vulkan: a `set`, `push_constant`, `constant_id` or
// `input_attachment_index` layout qualifier, or gl_VertexIndex / gl_InstanceIndex (glslang's OpenGL
// rules accept `set` too, so its compile does not tell).
bool writtenForVulkan(std::string_view text) {
  bool afterLayout = false;
  int layoutDepth = 0;
  for (const source::Token& t : source::lex(text)) {
    if (t.kind == source::TokenKind::Comment || t.directive != source::DirectiveKind::None) continue;
    const std::string_view word = source::tokenText(text, t);
    if (t.kind == source::TokenKind::Identifier) {
      if (word == "gl_VertexIndex" || word == "gl_InstanceIndex") return true;
      if (layoutDepth > 0 && (word == "set" || word == "push_constant" || word == "constant_id" ||
                              word == "input_attachment_index"))
        return true;
      afterLayout = word == "layout";
      continue;
    }
    if (word == "(" && (afterLayout || layoutDepth > 0)) ++layoutDepth;
    else if (word == ")" && layoutDepth > 0) --layoutDepth;
    afterLayout = false;
  }
  return false;
}

// GLSL that glslang accepts with Vulkan rules is taken as Vulkan GLSL even where OpenGL rules accept
// it too. Two OpenGL binding classes at one binding (a sampler and a uniform block both at 0) say it
// is OpenGL GLSL, since Vulkan cannot bind that: *result becomes the conversion with OpenGL rules
// where those accept it. GLSL written for Vulkan (writtenForVulkan) keeps its clash, which the
// harness then reports. Unless --target-env chose the rules.
void preferOpenGLRulesForOpenGLBindings(const SourceFile& file, const TranspileOptions& o, TranspileResult* result,
                                        std::optional<spirv::Module>* original) {
  if (o.targetEnv || result->source.language != SourceLanguage::Glsl || !result->source.vulkan ||
      !sharesBindingAcrossOpenGLClasses(**original) || writtenForVulkan(file.contents))
    return;
  TranspileOptions gl = o;
  gl.targetEnv = TargetEnv::OpenGL45;
  TranspileResult asOpenGL = transpile(file, gl);
  if (!asOpenGL.ok) return;
  std::string error;
  auto parsed = spirv::Module::parse(asOpenGL.originalSpirv, &error);
  if (!parsed) return;
  *result = std::move(asOpenGL);
  *original = std::move(parsed);
}

}  // namespace

bool buildStageModules(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                       std::vector<StageModules>* stages, std::string* classification, Diagnostics& diags) {
  std::vector<const SourceFile*> ordered;
  for (const auto& s : sources) {
    auto stage = decideStage(s.path, s.contents, options.stage, options.stageExtensions).stage;
    if (stage && isPreRasterization(*stage)) ordered.push_back(&s);
  }
  if (ordered.empty()) {
    diags.error(sources.empty() ? std::string() : sources.front().path,
                "nothing to verify: no vertex, tessellation or geometry stage");
    return false;
  }
  std::stable_sort(ordered.begin(), ordered.end(), [&](const SourceFile* a, const SourceFile* b) {
    auto of = [&](const SourceFile* f) { return decideStage(f->path, f->contents, options.stage, options.stageExtensions).stage; };
    return static_cast<int>(*of(a)) < static_cast<int>(*of(b));
  });
  // Converted as one pipeline, as `build` and `--pipeline` convert it: the eye parameters then take
  // a binding no stage of it uses (each stage alone could pick one another stage holds).
  TranspileOptions harnessOptions = options;
  harnessOptions.target = TargetLanguage::Spirv;
  harnessOptions.forceReemit = true;
  // The harness repairs what glslang's module for OpenGL GLSL gets wrong (a loose `uniform bool`)
  // in its own copies, original and transpiled alike (convertOpenGLForVulkan).
  harnessOptions.spirvForHarness = true;
  std::vector<SourceFile> orderedFiles;
  for (const SourceFile* file : ordered) orderedFiles.push_back(*file);
  std::vector<TranspileResult> converted = transpilePipeline(orderedFiles, harnessOptions);
  for (size_t i = 0; i < ordered.size(); ++i) {
    // The single-pass modes refuse what the output language cannot express (ESSL vertex shaders
    // and gl_Layer, OpenGL multiview and geometry stages, ...): verify runs SPIR-V, so it first
    // converts for the output the user asked for and reports that conversion's refusal as its own.
    if (options.eye.select != EyeSelect::Parameter && options.target != TargetLanguage::Spirv) {
      TranspileOptions asAsked = options;
      asAsked.shiftThisStage = i + 1 == ordered.size();
      TranspileResult check = transpile(*ordered[i], asAsked);
      if (!check.ok) {
        diags.append(check.diagnostics);
        return false;
      }
    }
    TranspileOptions o = harnessOptions;
    o.shiftThisStage = i + 1 == ordered.size();
    TranspileResult result = std::move(converted[i]);
    if (!result.ok) {
      diags.append(result.diagnostics);
      return false;
    }
    std::string error;
    auto original = spirv::Module::parse(result.originalSpirv, &error);
    if (!original) {
      diags.append(result.diagnostics);
      diags.error(ordered[i]->path, error);
      return false;
    }
    preferOpenGLRulesForOpenGLBindings(*ordered[i], o, &result, &original);
    diags.append(result.diagnostics);
    *classification = result.record.classification ? toString(*result.record.classification) : "";
    std::vector<uint32_t> words(result.output.size() / 4);
    std::memcpy(words.data(), result.output.data(), words.size() * 4);
    std::vector<std::string> halo = outputsExpectedToDiffer(result);
    const BindingClasses bindings = bindingClassesOf(result);
    stages->push_back({toVk(original->executionModel()), std::move(result.originalSpirv), std::move(words),
                       original->entryPointName(), std::move(halo), result.record.passes.halo.movedLanes, bindings});
  }
  return true;
}

}  // namespace stereoshift::harness
