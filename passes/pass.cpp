// What passes share besides the analyses: whether a shader is stereo already, and where free bindings are.
#include "passes/pass.h"

#include <cctype>

namespace stereoshift {

bool carriesEyeParameters(const PassContext& context) {
  bool eyeSign = false, separation = false;
  for (const auto& n : context.module.allNames()) {
    eyeSign |= n == context.options.eye.eyeSignName;
    separation |= n == context.options.eye.separationName;
  }
  return eyeSign && separation;
}

std::string alreadyStereoReason(const PassContext& context) {
  if (carriesEyeParameters(context))
    return "already carries stereo eye parameters ('" + context.options.eye.eyeSignName + "')";
  const spirv::Module& m = context.module;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && m.decorationValue(inst.resultId, spv::DecorationBuiltIn) ==
                                              static_cast<uint32_t>(spv::BuiltInViewIndex))
      return "reads the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID): it is multiview stereo already";
  // glslang 12 reads HLSL's SV_ViewID as a plain input and keeps only its semantic string.
  for (const auto& inst : m.annotations) {
    if (inst.opcode != spv::OpDecorateString || inst.operand(1) != uint32_t(spv::DecorationUserSemantic)) continue;
    std::string semantic = inst.stringOperand(2);
    for (char& c : semantic) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (semantic == "SV_VIEWID" && m.storageClassOf(inst.operand(0)) == spv::StorageClassInput)
      return "reads the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID): it is multiview stereo already";
  }
  return "";
}

bool perClassRegisters(const SourceInfo& source) {
  return source.language == SourceLanguage::Hlsl && !source.vulkanBindings;
}

std::optional<uint32_t> highestBinding(const spirv::Module& m, uint32_t set, bool constantBuffersOnly) {
  std::optional<uint32_t> highest;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    if (constantBuffersOnly && inst.operand(0) != spv::StorageClassUniform) continue;
    auto binding = m.decorationValue(inst.resultId, spv::DecorationBinding);
    if (!binding || m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0) != set) continue;
    highest = std::max(highest.value_or(0), *binding);
  }
  return highest;
}

}  // namespace stereoshift
