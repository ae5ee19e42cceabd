#include "passes/ir/validate.h"

#include <spirv-tools/libspirv.hpp>

namespace stereoshift {

namespace {

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
  // Vulkan: the oldest Vulkan version that takes the module's SPIR-V version (--target-env/--target-spv).
  if (version >= 0x00010600) return SPV_ENV_VULKAN_1_3;
  if (version >= 0x00010500) return SPV_ENV_VULKAN_1_2;
  if (version >= 0x00010400) return SPV_ENV_VULKAN_1_1_SPIRV_1_4;
  if (version >= 0x00010100) return SPV_ENV_VULKAN_1_1;
  return SPV_ENV_VULKAN_1_0;
}

}  // namespace

namespace {

std::string errorsUnder(const std::vector<uint32_t>& words, spv_target_env env, bool relaxLayout) {
  spvtools::SpirvTools tools(env);
  std::string messages;
  tools.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
    if (level <= SPV_MSG_ERROR) messages += std::string(message) + "\n";
  });
  spvtools::ValidatorOptions options;
  options.SetRelaxBlockLayout(relaxLayout);
  if (tools.Validate(words.data(), words.size(), options)) return "";
  while (!messages.empty() && messages.back() == '\n') messages.pop_back();
  return messages.empty() ? "the validator refused the module without a message" : messages;
}

}  // namespace

std::string vulkan10StrictLayoutErrors(const std::vector<uint32_t>& words) {
  if (!errorsUnder(words, SPV_ENV_VULKAN_1_0, true).empty()) return "";
  return errorsUnder(words, SPV_ENV_VULKAN_1_0, false);
}

std::string validationErrors(const std::vector<uint32_t>& words, const SourceInfo& info) {
  uint32_t version = words.size() > 1 ? words[1] : 0;
  spvtools::SpirvTools tools(environmentFor(info, version));
  std::string messages;
  tools.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
    if (level <= SPV_MSG_ERROR) messages += std::string(message) + "\n";
  });
  spvtools::ValidatorOptions options;
  options.SetRelaxBlockLayout(true);  // HLSL offsets (glslang's EShMsgHlslOffsets)
  if (tools.Validate(words.data(), words.size(), options)) return "";
  while (!messages.empty() && messages.back() == '\n') messages.pop_back();
  return messages.empty() ? "the validator refused the module without a message" : messages;
}

bool validateSpirv(const std::vector<uint32_t>& words, const SourceInfo& info, const std::string& file,
                   const std::string& when, Diagnostics& diags, const std::vector<uint32_t>* frontEnd,
                   std::string* inherited) {
  std::string messages = validationErrors(words, info);
  if (messages.empty()) return true;
  if (frontEnd && !frontEnd->empty() && validationErrors(*frontEnd, info) == messages) {
    if (inherited) *inherited = messages;
    return true;
  }
  diags.error(file, "invalid SPIR-V " + when + ": " + messages);
  return false;
}

}  // namespace stereoshift
