// The route list (route.h) and the routes that need no text of their own: the input copied through,
// SPIR-V as a binary, SPIR-V as assembly.
#include "transpiler/backend/route.h"

#include "transpiler/backend/reemit_route.h"
#include "transpiler/backend/splice_routes.h"

#include <algorithm>
#include <cstring>

namespace stereoshift {

TargetLanguage resolveTarget(const SourceInfo& info, const BackEndOptions& options) {
  if (options.target != TargetLanguage::Auto) return options.target;
  switch (info.language) {
    case SourceLanguage::Hlsl: return TargetLanguage::Hlsl;
    case SourceLanguage::Spirv: return TargetLanguage::Spirv;
    case SourceLanguage::Glsl: return info.es ? TargetLanguage::Essl : TargetLanguage::Glsl;
  }
  return TargetLanguage::Glsl;
}

bool sameLanguageOutput(const SourceInfo& info, TargetLanguage target, const BackEndOptions& options) {
  return (info.language == SourceLanguage::Spirv && target == TargetLanguage::Spirv) ||
         (info.language == SourceLanguage::Hlsl && target == TargetLanguage::Hlsl) ||
         (info.language == SourceLanguage::Glsl && target == (info.es ? TargetLanguage::Essl : TargetLanguage::Glsl) &&
          !options.targetVersion);
}

void decideOutputCapability(const SourceInfo& info, TargetLanguage target, PassOutput& output) {
  if (info.language != SourceLanguage::Hlsl || target != TargetLanguage::Hlsl) return;
  // SPIRV-Cross cannot write these stages as HLSL: the HLSL source splice writes geometry and
  // domain shaders (the eye parameters and the shift), and a hull shader is copied as it is.
  if (info.stage == Stage::Geometry || info.stage == Stage::TessEvaluation) {
    output.carries = EditKind::EyeParameters | EditKind::PositionShift;
    output.limitedBecause = "HLSL geometry and domain shaders back to HLSL are spliced into their own text";
  } else if (info.stage == Stage::TessControl) {
    output.carries = kNoEdits;
    output.limitedBecause = "HLSL hull shaders cannot be re-emitted as HLSL";
  }
}

namespace {

// Nothing to inject: the input is already its own drop-in replacement, byte for byte.
class CopyThroughRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "copy-through"; }
  bool needsValidModule() const override { return false; }
  bool takesStereoParamsTexture() const override { return true; }  // a copy reads no eye parameters
  RouteDecision accepts(const EmitRequest& r) const override {
    if (r.changed || r.options.forceReemit || !sameLanguageOutput(r.context.source, r.target, r.options))
      return RouteDecision::decline("the shader changed, or another language or version is asked for");
    return RouteDecision::accept();
  }
  EmitResult emit(const EmitRequest& r, EmitFacts&, Diagnostics&) const override {
    EmitResult result;
    result.status = EmitResult::Emitted;
    result.output = r.input.contents;
    result.binary = r.context.source.language == SourceLanguage::Spirv;
    result.copied = true;
    return result;
  }
};

// glslang's module for some OpenGL GLSL (a loose `uniform bool`) does not validate: fine in the
// GLSL / HLSL / MSL SPIRV-Cross writes from it, not as SPIR-V — except for verify, whose harness
// repairs its copy before running it.
RouteDecision acceptSpirv(const EmitRequest& r, TargetLanguage wanted) {
  if (r.target != wanted) return RouteDecision::decline("not a SPIR-V target");
  if (!r.inheritedInvalid.empty() && !r.options.spirvForHarness)
    return RouteDecision::refuse("glslang's SPIR-V for this shader does not validate (" + r.inheritedInvalid +
                                 "); it cannot be written as SPIR-V (choose a source-language --target)");
  return RouteDecision::accept();
}

class SpirvBinaryRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "spirv"; }
  RouteDecision accepts(const EmitRequest& r) const override { return acceptSpirv(r, TargetLanguage::Spirv); }
  EmitResult emit(const EmitRequest& r, EmitFacts&, Diagnostics&) const override {
    EmitResult result;
    result.status = EmitResult::Emitted;
    result.output.resize(r.finalWords.size() * 4);
    std::memcpy(result.output.data(), r.finalWords.data(), result.output.size());
    result.binary = true;
    return result;
  }
};

class SpirvAssemblyRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "spirv-asm"; }
  RouteDecision accepts(const EmitRequest& r) const override { return acceptSpirv(r, TargetLanguage::SpirvAsm); }
  EmitResult emit(const EmitRequest& r, EmitFacts&, Diagnostics&) const override {
    EmitResult result;
    result.status = EmitResult::Emitted;
    result.output = spirv::disassemble(r.finalWords);
    return result;
  }
};

}  // namespace

const std::vector<std::unique_ptr<BackEndRoute>>& routes() {
  static const std::vector<std::unique_ptr<BackEndRoute>> list = [] {
    std::vector<std::unique_ptr<BackEndRoute>> l;
    l.push_back(std::make_unique<CopyThroughRoute>());
    l.push_back(std::make_unique<SpirvBinaryRoute>());
    l.push_back(std::make_unique<SpirvAssemblyRoute>());
    l.push_back(createHlslSpliceRoute());
    l.push_back(createHlslPixelSpliceRoute());
    l.push_back(createHlslUnprojectionSpliceRoute());
    l.push_back(createLegacyGlslRoute());
    l.push_back(createGlslSpliceRoute());
    l.push_back(createReemitRoute());  // takes every stage the others decline
    return l;
  }();
  return list;
}

}  // namespace stereoshift
