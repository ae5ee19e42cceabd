#include "transpiler/pipeline.h"

#include <spirv-tools/libspirv.hpp>

#include <algorithm>

namespace stereoshift {

namespace {

struct PipelineEntry {
  std::unique_ptr<Pass> (*create)();
};

// The order matters:
//  1. clip-position-detection is analysis only: it classifies the shader; the geometry passes
//     below do nothing unless it found a perspective last stage.
//  2. hud-at-depth (opt-in) turns a proven-2D position into one at an eye depth, which then needs
//     the shift like any perspective position: it must come before eye-params, halo and the shift.
//  3. eye-params declares eyeSign / separation / convergence; the shift and halo code load them.
//  4. halo runs before the shift, while the only loads of the position are the application's own,
//     so it sees exactly the values the application derived its outputs from.
//  5. stereo-shift guards and shifts the final position at every return / emit.
//  6. per-eye-view and deferred-unprojection fix pixel maths that sees the mono eye; they are
//     independent of the shift (they also run on fragment shaders, which get no shift) and declare
//     the eye parameters they need themselves.
const PipelineEntry kPipeline[] = {
    {createClipPositionDetectionPass},
    {createHudAtDepthPass},
    {createEyeParamsPass},
    {createHaloPass},
    {createStereoShiftPass},
    {createPerEyeViewPass},
    {createDeferredUnprojectionPass},
};

spv_target_env environmentFor(const SourceInfo& info, uint32_t version) {
  if (info.language == SourceLanguage::Glsl && !info.vulkan) return SPV_ENV_OPENGL_4_5;
  if (info.language == SourceLanguage::Spirv) {
    switch (version) {
      case 0x00010000: return SPV_ENV_UNIVERSAL_1_0;
      case 0x00010100: return SPV_ENV_UNIVERSAL_1_1;
      case 0x00010200: return SPV_ENV_UNIVERSAL_1_2;
      case 0x00010300: return SPV_ENV_UNIVERSAL_1_3;
      case 0x00010400: return SPV_ENV_UNIVERSAL_1_4;
      case 0x00010500: return SPV_ENV_UNIVERSAL_1_5;
      default: return SPV_ENV_UNIVERSAL_1_6;
    }
  }
  return SPV_ENV_VULKAN_1_0;
}

}  // namespace

bool validateSpirv(const std::vector<uint32_t>& words, const SourceInfo& info, const std::string& file,
                   const std::string& when, Diagnostics& diags) {
  uint32_t version = words.size() > 1 ? words[1] : 0;
  spvtools::SpirvTools tools(environmentFor(info, version));
  std::string messages;
  tools.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
    if (level <= SPV_MSG_ERROR) messages += std::string(message) + "\n";
  });
  spvtools::ValidatorOptions options;
  options.SetRelaxBlockLayout(true);  // HLSL offsets (glslang's EShMsgHlslOffsets)
  if (tools.Validate(words.data(), words.size(), options)) return true;
  while (!messages.empty() && messages.back() == '\n') messages.pop_back();
  diags.error(file, "invalid SPIR-V " + when + ": " + messages);
  return false;
}

bool runPassPipeline(PassContext& ctx, bool* changed, std::string* passLog) {
  *changed = false;
  for (const auto& entry : kPipeline) {
    auto pass = entry.create();
    const auto& only = ctx.options.onlyPasses;
    if (!only.empty() && std::find(only.begin(), only.end(), pass->name()) == only.end()) continue;
    PassResult result = pass->run(ctx);
    ctx.report["passes"][pass->name()]["result"] = toString(result);
    if (result == PassResult::Failed) return false;
    if (result == PassResult::Changed) *changed = true;
    if (ctx.options.printAll && passLog)
      *passLog += "; IR after " + std::string(pass->name()) + " (" + toString(result) + ")\n" +
                  spirv::disassemble(ctx.module.encode());
    if (ctx.options.validateEach && result == PassResult::Changed &&
        !validateSpirv(ctx.module.encode(), ctx.source, ctx.file, std::string("after pass ") + pass->name(),
                       ctx.diags))
      return false;
  }
  return true;
}

}  // namespace stereoshift
