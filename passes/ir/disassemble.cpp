#include "passes/ir/disassemble.h"

#include <spirv-tools/libspirv.hpp>

namespace stereoshift::spirv {

std::string disassemble(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(SPV_ENV_UNIVERSAL_1_6);
  std::string text;
  tools.Disassemble(words, &text,
                    SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT);
  return text;
}

std::vector<uint32_t> assemble(const std::string& text, std::string* error) {
  spvtools::SpirvTools tools(SPV_ENV_UNIVERSAL_1_6);
  std::string messages;
  tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& position,
                               const char* message) {
    messages += std::to_string(position.line + 1) + ":" + std::to_string(position.column + 1) +
                ": error: " + message + "\n";
  });
  std::vector<uint32_t> words;
  if (!tools.Assemble(text, &words, SPV_TEXT_TO_BINARY_OPTION_PRESERVE_NUMERIC_IDS)) {
    if (error) *error = messages.empty() ? "invalid SPIR-V assembly" : messages;
    return {};
  }
  return words;
}

}  // namespace stereoshift::spirv
