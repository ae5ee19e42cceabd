// See sources.h.
#include "passes/deferred_unprojection/sources.h"

#include "passes/ir/image_instructions.h"

#include <cctype>

namespace stereoshift::deferred {

using analysis::kAnyIndex;
using spirv::Instruction;

std::string lower(std::string text) {
  for (auto& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "?" : out;
}

bool isFragCoord(const spirv::Module& m, uint32_t root, const AccessPath& path) {
  if (m.decorationValue(root, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInFragCoord)) return true;
  const Instruction* var = m.definition(root);
  if (!var || path.empty() || path[0] == kAnyIndex) return false;
  return m.memberDecorationValue(m.pointeeType(var->typeId), path[0], spv::DecorationBuiltIn) ==
         uint32_t(spv::BuiltInFragCoord);
}

// A variable (and the member a path starts with) as the source names it.
std::string describe(const spirv::Module& m, uint32_t root, const AccessPath& path) {
  const Instruction* var = m.definition(root);
  std::string name = m.name(root);
  if (var && !path.empty() && path[0] != kAnyIndex) {
    uint32_t type = m.pointeeType(var->typeId);
    const Instruction* typeDef = m.definition(type);
    if (typeDef && typeDef->opcode == spv::OpTypeStruct) {
      std::string member = m.memberName(type, path[0]);
      // HLSL cbuffers and globals are anonymous instances: their members are what the source names.
      if (name.empty() || name == "$Global") return member;
      return name + "." + member;
    }
  }
  return name.empty() ? "%" + std::to_string(root) : name;
}

namespace {

// The lanes of an input that (root, path) reads: the one lane a path ending in a vector's
// component names, else every lane of the vector it ends at; none for a scalar input, a whole value
// that tells no x from y (an interpolated w, `float v2 : TEXCOORD1`, that `v1.xy / v2.x` divides by).
uint32_t inputLanesOf(const spirv::Module& m, uint32_t root, const AccessPath& path) {
  const Instruction* var = m.definition(root);
  if (!var) return 0xFu;
  uint32_t type = m.pointeeType(var->typeId);
  for (uint32_t step : path) {
    const Instruction* t = m.definition(type);
    if (!t || step == kAnyIndex) return 0xFu;
    if (t->opcode == spv::OpTypeVector) return step < 32 ? 1u << step : 0xFu;
    if (t->opcode == spv::OpTypeStruct && step < t->operands.size()) type = t->operand(step);
    else if (t->opcode == spv::OpTypeArray) type = t->operand(0);
    else return 0xFu;
  }
  const Instruction* t = m.definition(type);
  if (t && t->opcode == spv::OpTypeVector) return (1u << t->operand(1)) - 1;
  return 0u;
}

}  // namespace

Sources SourceRules::unknown() const {
  Sources s;
  s.other = true;
  return s;
}

std::optional<Sources> SourceRules::leaf(const Instruction& def, const AccessPath&) const {
  const spirv::Module& m = flow_.module();
  Sources s;
  if (eyeParameters_.count(def.resultId)) {  // a specialization constant
    s.uniform = s.eyeParameter = true;
    return s;
  }
  if (opaqueProducts_.count(def.resultId)) {
    s.products.insert(def.resultId);
    return s;
  }
  switch (def.opcode) {
    case spv::OpConstant: case spv::OpConstantTrue: case spv::OpConstantFalse: case spv::OpConstantNull:
      s.constant = true;
      s.constantOtherThanOne = m.floatConstant(def.resultId) != 1.0f;
      return s;
    case spv::OpSpecConstant: case spv::OpSpecConstantTrue: case spv::OpSpecConstantFalse:
    case spv::OpSpecConstantComposite: case spv::OpSpecConstantOp:
      s.uniform = true;  // chosen by the application, like a uniform
      return s;
    case spv::OpImageQuerySize: case spv::OpImageQuerySizeLod: case spv::OpImageQueryLevels:
    case spv::OpImageQuerySamples:
      // A texture's size (HLSL's GetDimensions, textureSize): the same for every pixel of a draw,
      // chosen by the application like a uniform (a pixel position over the screen texture's
      // size is a UV, as over a cbuffer's screen size).
      s.uniform = true;
      s.textures.insert(imageName(def.operand(0)));
      return s;
    default:
      // A texel; a depth comparison is not a depth, and stays unknown.
      if (spirv::isTexelRead(def.opcode)) {
        s.texel = true;
        s.textures.insert(imageName(def.operand(0)));
        return s;
      }
      return std::nullopt;
  }
}

Sources SourceRules::moduleVariable(const Instruction& variable, const AccessPath& path) const {
  const spirv::Module& m = flow_.module();
  uint32_t root = variable.resultId;
  Sources s;
  switch (static_cast<spv::StorageClass>(variable.operand(0))) {
    case spv::StorageClassInput:
      if (isFragCoord(m, root, path)) {
        // Only x, y are the pixel position; z (the fragment's depth) and w are the same per eye.
        size_t component = m.hasDecoration(root, spv::DecorationBuiltIn) ? 0 : 1;
        if (path.size() > component && (path[component] == 2 || path[component] == 3)) {
          Sources depthOrW = unknown();
          depthOrW.fragmentDepth = path[component] == 2;
          return depthOrW;
        }
        s.fragCoord = true;
        s.inputLanes = inputLanesOf(m, root, path);
        s.inputs.insert(hlsl_ ? "SV_Position" : "gl_FragCoord");
      } else if (m.hasDecoration(root, spv::DecorationBuiltIn)) {
        s.other = true;  // gl_FrontFacing, gl_SampleID, ...: not a screen position
      } else {
        s.varying = true;
        s.inputLanes = inputLanesOf(m, root, path);
        s.inputs.insert(describe(m, root, path));
      }
      return s;
    case spv::StorageClassUniform: case spv::StorageClassUniformConstant:
    case spv::StorageClassPushConstant: case spv::StorageClassStorageBuffer:
      s.uniform = true;
      s.eyeParameter = eyeParameters_.count(root) > 0;
      s.uniforms.insert(describe(m, root, path));
      return s;
    default:
      return unknown();
  }
}

void SourceRules::computed(const Instruction& def, Sources& s) const {
  s.arithmetic = true;
  if (def.opcode == spv::OpMatrixTimesVector || def.opcode == spv::OpVectorTimesMatrix) s.products.insert(def.resultId);
}

std::string SourceRules::imageName(uint32_t image) const {
  for (int depth = 0; depth < 16; ++depth) {
    const Instruction* def = flow_.definition(image);
    if (!def) break;
    if (def->opcode == spv::OpSampledImage || def->opcode == spv::OpImage || def->opcode == spv::OpCopyObject) {
      image = def->operand(0);
      continue;
    }
    if (def->opcode == spv::OpLoad)
      if (auto target = flow_.resolvePointer(def->operand(0))) return describe(flow_.module(), target->root, target->path);
    break;
  }
  return "?";
}

}  // namespace stereoshift::deferred
