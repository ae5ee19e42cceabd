// What verify does to its own copies of the modules before they run (see harness_rewrites.h).
#include "transpiler/verify/harness_rewrites.h"

#include "transpiler/verify/stage_synthesis.h"
#include "passes/ir/builder.h"
#include "passes/ir/module.h"

#include <algorithm>
#include <map>

namespace stereoshift::harness {

using spirv::Instruction;
using spirv::Module;

namespace {

// Takes `variable` out of every entry point's interface list (nothing reads it any more).
void dropFromInterface(Module& m, uint32_t variable) {
  for (auto& entry : m.entryPoints) {
    const size_t first = 2 + entry.stringWordCount(2);
    for (size_t i = first; i < entry.operands.size(); ++i)
      if (entry.operands[i] == variable) {
        entry.operands.erase(entry.operands.begin() + long(i));
        break;
      }
  }
}

// The resource a variable holds: the type under its pointer and any descriptor arrays.
const Instruction* resourceType(const Module& m, const Instruction& variable) {
  const Instruction* def = m.definition(m.pointeeType(variable.typeId));
  while (def && (def->opcode == spv::OpTypeArray || def->opcode == spv::OpTypeRuntimeArray)) def = m.definition(def->operand(0));
  return def;
}

// Adds shiftOf[variable] to the Binding of each variable there.
void shiftBindings(Module& m, const std::map<uint32_t, uint32_t>& shiftOf) {
  for (auto& inst : m.annotations)
    if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationBinding))
      if (auto it = shiftOf.find(inst.operand(0)); it != shiftOf.end()) inst.operands[2] += it->second;
}

}  // namespace

VkShaderStageFlagBits toVk(spv::ExecutionModel model) {
  switch (model) {
    case spv::ExecutionModelTessellationControl: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case spv::ExecutionModelTessellationEvaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    case spv::ExecutionModelGeometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    default: return VK_SHADER_STAGE_VERTEX_BIT;
  }
}

// A push-constant block larger than the device allows (lavapipe: maxPushConstantsSize) cannot be
// pushed; the harness turns it into a uniform buffer at (set, 0) instead — the same bytes, read
// through the same offsets (the device's uniformBufferStandardLayout lets the std430 layout of
// push constants stand), identically in the original and the transpiled module.
void pushConstantsToUniformBuffer(Module& m, uint32_t set) {
  for (auto& inst : m.typesValues) {
    if (inst.opcode == spv::OpTypePointer && inst.operand(0) == uint32_t(spv::StorageClassPushConstant))
      inst.operands[0] = spv::StorageClassUniform;
    if (inst.opcode == spv::OpVariable && inst.operand(0) == uint32_t(spv::StorageClassPushConstant)) {
      inst.operands[0] = spv::StorageClassUniform;
      m.decorate(inst.resultId, spv::DecorationDescriptorSet, {set});
      m.decorate(inst.resultId, spv::DecorationBinding, {0});
    }
  }
  m.invalidateDefinitions();
}

// The device features a module's capabilities need; empty when the device has them all.
std::string missingFeature(const Module& m, const VkPhysicalDeviceFeatures& f) {
  struct Need {
    spv::Capability capability;
    VkBool32 VkPhysicalDeviceFeatures::*feature;
    const char* capabilityName;
    const char* featureName;
  };
  static const Need needs[] = {
      {spv::CapabilityFloat64, &VkPhysicalDeviceFeatures::shaderFloat64, "Float64", "shaderFloat64"},
      {spv::CapabilityInt64, &VkPhysicalDeviceFeatures::shaderInt64, "Int64", "shaderInt64"},
      {spv::CapabilityInt16, &VkPhysicalDeviceFeatures::shaderInt16, "Int16", "shaderInt16"},
      {spv::CapabilityGeometryPointSize, &VkPhysicalDeviceFeatures::shaderTessellationAndGeometryPointSize,
       "GeometryPointSize", "shaderTessellationAndGeometryPointSize"},
      {spv::CapabilityTessellationPointSize, &VkPhysicalDeviceFeatures::shaderTessellationAndGeometryPointSize,
       "TessellationPointSize", "shaderTessellationAndGeometryPointSize"},
      {spv::CapabilityClipDistance, &VkPhysicalDeviceFeatures::shaderClipDistance, "ClipDistance", "shaderClipDistance"},
      {spv::CapabilityCullDistance, &VkPhysicalDeviceFeatures::shaderCullDistance, "CullDistance", "shaderCullDistance"},
      {spv::CapabilitySampledCubeArray, &VkPhysicalDeviceFeatures::imageCubeArray, "SampledCubeArray", "imageCubeArray"},
      {spv::CapabilityImageCubeArray, &VkPhysicalDeviceFeatures::imageCubeArray, "ImageCubeArray", "imageCubeArray"},
      {spv::CapabilityStorageImageReadWithoutFormat, &VkPhysicalDeviceFeatures::shaderStorageImageReadWithoutFormat,
       "StorageImageReadWithoutFormat", "shaderStorageImageReadWithoutFormat"},
      {spv::CapabilityStorageImageWriteWithoutFormat, &VkPhysicalDeviceFeatures::shaderStorageImageWriteWithoutFormat,
       "StorageImageWriteWithoutFormat", "shaderStorageImageWriteWithoutFormat"},
      {spv::CapabilityStorageImageExtendedFormats, &VkPhysicalDeviceFeatures::shaderStorageImageExtendedFormats,
       "StorageImageExtendedFormats", "shaderStorageImageExtendedFormats"},
      {spv::CapabilityMultiViewport, &VkPhysicalDeviceFeatures::multiViewport, "MultiViewport", "multiViewport"},
      {spv::CapabilityImageGatherExtended, &VkPhysicalDeviceFeatures::shaderImageGatherExtended,
       "ImageGatherExtended", "shaderImageGatherExtended"},
  };
  for (const Need& n : needs)
    if (m.hasCapability(n.capability) && !(f.*n.feature))
      return std::string("the ") + executionModelName(m.executionModel()) + " shader needs the " + n.featureName +
             " device feature (SPIR-V capability " + n.capabilityName + "), which this device lacks";
  return {};
}

// Double-precision vertex inputs (dvec3 positions of CAD-style samples) need 64-bit vertex
// formats, which lavapipe does not have. The harness feeds them as 32-bit floats instead: each
// such input becomes a float input at the same location whose loads are converted to double, in
// the original and the transpiled module alike (the generated data are floats anyway).
void feedDoubleInputsAsFloats(Module& m) {
  if (m.executionModel() != spv::ExecutionModelVertex) return;
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->operand(0) != spv::StorageClassInput || m.hasDecoration(id, spv::DecorationBuiltIn)) continue;
    const uint32_t doubleType = m.pointeeType(var->typeId);
    const Instruction* d = m.definition(doubleType);
    const uint32_t n = d && d->opcode == spv::OpTypeVector ? d->operand(1) : 1;
    const Instruction* scalar = d && d->opcode == spv::OpTypeVector ? m.definition(d->operand(0)) : d;
    if (!scalar || scalar->opcode != spv::OpTypeFloat || scalar->operand(0) != 64) continue;
    const uint32_t doubleScalar = scalar->resultId;
    const uint32_t floatScalar = m.typeFloat(32);
    const uint32_t floatType = n > 1 ? m.typeVector(floatScalar, n) : floatScalar;
    const uint32_t floatVar = m.addGlobalVariable(m.typePointer(spv::StorageClassInput, floatType), spv::StorageClassInput);
    const uint32_t floatScalarPointer = m.typePointer(spv::StorageClassInput, floatScalar);
    for (auto decoration : {spv::DecorationLocation, spv::DecorationComponent})
      if (auto value = m.decorationValue(id, decoration)) m.decorate(floatVar, decoration, {*value});
    m.setName(floatVar, m.name(id));
    dropFromInterface(m, id);  // the double variable is no longer read
    std::vector<uint32_t> chains;  // access chains into the old variable, now into the float one
    for (auto& f : m.functions)
      for (auto& b : f.blocks) {
        std::vector<Instruction> rewritten;
        for (auto& inst : b.instructions) {
          if ((inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain) && inst.operand(0) == id) {
            inst.typeId = floatScalarPointer;
            inst.operands[0] = floatVar;
            chains.push_back(inst.resultId);
          } else if (inst.opcode == spv::OpLoad &&
                     (inst.operand(0) == id ||
                      std::find(chains.begin(), chains.end(), inst.operand(0)) != chains.end())) {
            const bool whole = inst.operand(0) == id;
            spirv::Builder b(m, rewritten);
            const uint32_t loaded = b.load(whole ? floatType : floatScalar, whole ? floatVar : inst.operand(0));
            b.addAs(inst.resultId, spv::OpFConvert, whole ? doubleType : doubleScalar, {loaded});
            continue;
          }
          rewritten.push_back(std::move(inst));
        }
        b.instructions = std::move(rewritten);
      }
    m.invalidateDefinitions();
  }
}

// Vertices per input primitive of a geometry shader, and the list topology that feeds it.
uint32_t geometryInput(const Module& geometry, VkPrimitiveTopology* topology) {
  for (const auto& mode : geometry.executionModes) switch (mode.operand(1)) {
      case spv::ExecutionModeInputPoints: *topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST; return 1;
      case spv::ExecutionModeInputLines: *topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST; return 2;
      case spv::ExecutionModeInputLinesAdjacency: *topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST_WITH_ADJACENCY; return 4;
      case spv::ExecutionModeInputTrianglesAdjacency:
        *topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY;
        return 6;
      case spv::ExecutionModeTriangles: *topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST; return 3;
      default: break;
    }
  *topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  return 3;
}

// The transpiled shader marks its position Invariant (the shift must not be contracted differently
// per eye); a driver then compiles everything feeding the position without FMA contraction
// (llvmpipe does), so the original — contracted — would differ from it in the last bits at
// eyeSign = 0 for reasons that are not the injected code. The harness marks the same outputs
// Invariant in its copy of the original, so that both compile alike and eyeSign = 0 is compared bit
// for bit against the same arithmetic.
void matchInvariance(Module& original, const Module& transpiled) {
  auto builtIn = [](const Module& m, uint32_t id) { return m.decorationValue(id, spv::DecorationBuiltIn); };
  std::vector<std::pair<uint32_t, uint32_t>> memberBuiltIns;  // (struct, member) -> BuiltIn, in the original
  for (const auto& inst : transpiled.annotations) {
    if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationInvariant)) {
      const uint32_t target = inst.operand(0);
      auto b = builtIn(transpiled, target);
      for (const auto& v : original.typesValues)
        if (v.opcode == spv::OpVariable && v.operand(0) == uint32_t(spv::StorageClassOutput) &&
            !original.hasDecoration(v.resultId, spv::DecorationInvariant) &&
            (b ? builtIn(original, v.resultId) == b : original.name(v.resultId) == transpiled.name(target))) {
          original.decorate(v.resultId, spv::DecorationInvariant);
          break;
        }
    } else if (inst.opcode == spv::OpMemberDecorate && inst.operand(2) == uint32_t(spv::DecorationInvariant)) {
      auto b = transpiled.memberDecorationValue(inst.operand(0), inst.operand(1), spv::DecorationBuiltIn);
      if (!b) continue;
      for (const auto& d : original.annotations)
        if (d.opcode == spv::OpMemberDecorate && d.operand(2) == uint32_t(spv::DecorationBuiltIn) && d.operand(3) == *b &&
            !original.hasMemberDecoration(d.operand(0), d.operand(1), spv::DecorationInvariant))
          memberBuiltIns.push_back({d.operand(0), d.operand(1)});
    }
  }
  for (auto [structId, member] : memberBuiltIns) original.decorateMember(structId, member, spv::DecorationInvariant);
}

// Multiview: transform feedback must not be active in a multiview render pass, so the harness
// draws each view on its own, in a copy of the module whose reads of the view index (ViewIndex)
// read that view's number as a constant (harness-only, like the capture decorations): the shader's
// code computes exactly what it computes in that view of a view-mask-0b11 draw.
Status bindViewIndex(Module& m, uint32_t view) {
  uint32_t variable = 0;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable &&
        m.decorationValue(inst.resultId, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInViewIndex))
      variable = inst.resultId;
  if (!variable) return Done{};  // this stage does not read the view
  const uint32_t type = m.pointeeType(m.definition(variable)->typeId);
  const Instruction* typeDef = m.definition(type);
  const bool isSigned = typeDef && typeDef->opcode == spv::OpTypeInt && typeDef->operand(1) == 1;
  const uint32_t value = m.constantInt(int32_t(view));
  for (auto& f : m.functions)
    for (auto& b : f.blocks)
      for (auto& inst : b.instructions) {
        if (inst.opcode == spv::OpLoad && inst.operand(0) == variable) {
          inst.opcode = isSigned ? spv::OpCopyObject : spv::OpBitcast;  // HLSL's SV_ViewID is a uint
          inst.operands = {value};
          continue;
        }
        const bool pointerUse =
            (inst.opcode == spv::OpCopyMemory && inst.operand(1) == variable) ||
            ((inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain) && inst.operand(0) == variable) ||
            (inst.opcode == spv::OpFunctionCall &&
             std::find(inst.operands.begin() + 1, inst.operands.end(), variable) != inst.operands.end());
        if (pointerUse)
          return plainError("the " + std::string(executionModelName(m.executionModel())) +
                            " shader reads the view index other than by a load; the harness cannot run it per view");
      }
  dropFromInterface(m, variable);
  m.invalidateDefinitions();
  return Done{};
}

// Instanced: the vertex stage writes the eye to gl_Layer / gl_ViewportIndex, built-ins that the
// capture does not decorate for transform feedback. The harness's copy writes that same value to
// an ordinary int output instead, one location past every output the shader has, which the capture
// then reads like any other. Returns the output's name, empty when the shader writes no such built-in.
std::string exposeEyeRoute(Module& m, EyeRoute route) {
  const uint32_t builtIn = uint32_t(route == EyeRoute::Layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex);
  uint32_t variable = 0, location = 0;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != uint32_t(spv::StorageClassOutput)) continue;
    if (m.decorationValue(inst.resultId, spv::DecorationBuiltIn) == builtIn) variable = inst.resultId;
    if (auto l = m.decorationValue(inst.resultId, spv::DecorationLocation)) location = std::max(location, *l + 1);
  }
  if (!variable) return {};
  m.removeDecorations(variable, spv::DecorationBuiltIn);
  m.decorate(variable, spv::DecorationLocation, {location});
  const std::string name = route == EyeRoute::Layer ? "gl_Layer" : "gl_ViewportIndex";
  if (m.name(variable).empty()) m.setName(variable, name);
  return m.name(variable);
}

// See stereo_verify.h. The ranges: b (constant buffers) 0-15, s (samplers) 16-31, u (unordered
// access: RW buffers and textures) 32-95, t (shader resources: textures, read-only structured /
// byte-address buffers) 96 and up.
void separateRegisterClasses(Module& m) {
  constexpr uint32_t kSamplerShift = 16, kUavShift = 32, kTextureShift = 96;
  std::map<uint32_t, uint32_t> shiftOf;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    auto storage = static_cast<spv::StorageClass>(inst.operand(0));
    const Instruction* def = resourceType(m, inst);
    if (!def) continue;
    if (storage == spv::StorageClassUniform || storage == spv::StorageClassStorageBuffer) {
      bool buffer = storage == spv::StorageClassStorageBuffer || m.hasDecoration(def->resultId, spv::DecorationBufferBlock);
      if (!buffer) continue;  // a cbuffer: b, unmoved
      bool readOnly = m.hasDecoration(inst.resultId, spv::DecorationNonWritable) ||
                      (def->opcode == spv::OpTypeStruct && !def->operands.empty() &&
                       m.hasMemberDecoration(def->resultId, 0, spv::DecorationNonWritable));
      shiftOf[inst.resultId] = readOnly ? kTextureShift : kUavShift;
    } else if (storage == spv::StorageClassUniformConstant) {
      if (def->opcode == spv::OpTypeSampler) shiftOf[inst.resultId] = kSamplerShift;
      else if (def->opcode == spv::OpTypeImage) shiftOf[inst.resultId] = def->operand(5) == 2 ? kUavShift : kTextureShift;
      else if (def->opcode == spv::OpTypeSampledImage) shiftOf[inst.resultId] = kTextureShift;
    }
  }
  shiftBindings(m, shiftOf);
}

// OpenGL's binding namespaces, as the shift of each range (uniform blocks 0: unmoved). The default
// uniform block (16 + the stage's index) and the eye block the conversion added after the highest
// binding are uniform blocks and stay where they were put.
enum OpenGLBindingClass : uint32_t {
  kUniformBlock = 0, kTextureUnit = 256, kImage = 512, kStorageBlock = 768, kAtomicCounter = 1024, kNotBound = ~0u
};

OpenGLBindingClass openGLBindingClass(const Module& m, const Instruction& variable) {
  auto storage = static_cast<spv::StorageClass>(variable.operand(0));
  const Instruction* def = resourceType(m, variable);
  if (!def) return kNotBound;
  if (storage == spv::StorageClassStorageBuffer ||
      (storage == spv::StorageClassUniform && m.hasDecoration(def->resultId, spv::DecorationBufferBlock)))
    return kStorageBlock;
  if (storage == spv::StorageClassUniform) return kUniformBlock;
  if (storage == spv::StorageClassAtomicCounter) return kAtomicCounter;
  if (storage != spv::StorageClassUniformConstant) return kNotBound;
  if (def->opcode == spv::OpTypeImage) return def->operand(5) == 2 ? kImage : kTextureUnit;
  if (def->opcode == spv::OpTypeSampledImage || def->opcode == spv::OpTypeSampler) return kTextureUnit;
  return kNotBound;
}

// See stereo_verify.h.
void separateOpenGLBindingClasses(Module& m) {
  std::map<uint32_t, uint32_t> shiftOf;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable)
      if (OpenGLBindingClass c = openGLBindingClass(m, inst); c != kNotBound && c != kUniformBlock) shiftOf[inst.resultId] = c;
  shiftBindings(m, shiftOf);
}

// See harness_rewrites.h.
bool sharesBindingAcrossOpenGLClasses(const Module& m) {
  std::map<std::pair<uint32_t, uint32_t>, OpenGLBindingClass> classAt;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    const OpenGLBindingClass c = openGLBindingClass(m, inst);
    auto binding = m.decorationValue(inst.resultId, spv::DecorationBinding);
    if (c == kNotBound || !binding) continue;
    const std::pair<uint32_t, uint32_t> at{m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0), *binding};
    if (auto [it, added] = classAt.emplace(at, c); !added && it->second != c) return true;
  }
  return false;
}

}  // namespace stereoshift::harness
