// deferred-unprojection: turns a fragment shader's position rebuild from a stereo depth buffer,
// `q = InvM * vec4(ndc.xy, depth, 1)` (InvM a uniform matrix, depth a texel, ndc from gl_FragCoord /
// SV_Position or an interpolated full-screen UV), into the stereo-correct
//     q' = q - InvM[col 0] * eyeSign*separation*(1 - convergence*q.w)
// applied to q itself, before the perspective divide, and reports the view-dependent constructs it
// leaves alone (other matrix products, gl_FragCoord-based effects, reflections).
//
// Why this is exact (STEREO.md section 4): the G-buffer of an eye was rendered with the stereo
// projection, whose clip x is x + e*S*(w - C), so the pixel's NDC x is the mono one plus
// e*S*(1 - C/w) while y, z and w are the mono ones. By linearity InvM * (ndc + d*e0) = q_mono +
// d*InvM[col 0]. For a perspective projection (or a view-projection with an affine view) InvM maps
// NDC points to points divided by their eye depth w, so q.w = 1/w, and the w component of
// InvM[col 0] is 0 (an x offset in NDC is a direction), which leaves q.w unchanged: the offset is
// d = e*S*(1 - C*q.w), known from q alone. The same holds for the world form (InvM = inverse
// view-projection) and the view-space form (InvM = inverse projection); only the matrix already in
// the shader is needed. The ndc source does not matter: in each eye's image gl_FragCoord, a
// full-screen UV and an interpolated clip position all give that eye's (stereo) NDC.
//
// Recognition runs on the real module, through the unoptimised code glslang emits: function-local
// variables (every store that may reach a load), helper functions (pointer parameters followed to
// each call site, return values to each return) and structs (access paths), so the rewrite can
// replace the product's own result id, whose every use then sees q'. Component by component:
//   w: only moves from the literal 1.0 (a point, not a direction);
//   z: computed from a texel (sample, fetch or subpass read; a depth comparison is not a depth),
//      constants and uniforms only (`depth`, `depth*2-1`, a linear remap);
//   x, y: computed from gl_FragCoord or an input varying (fragment stage), uniforms and constants,
//      no texel;
//   the matrix: computed from uniform data only.
#include "passes/pass.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>

namespace stereoshift {

using spirv::Instruction;

namespace {

// An index of an access chain that is not a compile-time constant: it may address any element.
constexpr uint32_t kAnyIndex = 0xFFFFFFFFu;
using Path = std::vector<uint32_t>;

bool prefixOf(const Path& prefix, const Path& full) {
  if (prefix.size() > full.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (prefix[i] != full[i] && prefix[i] != kAnyIndex && full[i] != kAnyIndex) return false;
  return true;
}

// What a value is computed from.
struct Sources {
  bool fragCoord = false;  // gl_FragCoord / SV_Position
  bool varying = false;    // another fragment input (full-screen UV, interpolated clip position)
  bool texel = false;      // an image sample, fetch or read
  bool uniform = false;    // uniform, push-constant or specialization-constant data
  bool constant = false;
  bool other = false;      // anything the analysis does not see through
  bool arithmetic = false;            // computed, not only moved
  bool constantOtherThanOne = false;  // some constant leaf is not the float 1.0
  bool cycleCut = false;              // part of the answer was cut at a loop (not cached)
  bool eyeParameter = false;          // stereoshift's own eye parameters: injected code
  std::set<std::string> inputs, textures, uniforms;
  std::set<uint32_t> products;  // matrix x vector products the value went through

  Sources& operator|=(const Sources& o) {
    fragCoord |= o.fragCoord;
    varying |= o.varying;
    texel |= o.texel;
    uniform |= o.uniform;
    constant |= o.constant;
    other |= o.other;
    arithmetic |= o.arithmetic;
    constantOtherThanOne |= o.constantOtherThanOne;
    cycleCut |= o.cycleCut;
    eyeParameter |= o.eyeParameter;
    inputs.insert(o.inputs.begin(), o.inputs.end());
    textures.insert(o.textures.begin(), o.textures.end());
    uniforms.insert(o.uniforms.begin(), o.uniforms.end());
    products.insert(o.products.begin(), o.products.end());
    return *this;
  }
};

bool isImageRead(spv::Op op) {
  switch (op) {
    case spv::OpImageSampleImplicitLod: case spv::OpImageSampleExplicitLod:
    case spv::OpImageSampleProjImplicitLod: case spv::OpImageSampleProjExplicitLod:
    case spv::OpImageFetch: case spv::OpImageRead: case spv::OpImageGather:
    case spv::OpImageSparseSampleImplicitLod: case spv::OpImageSparseSampleExplicitLod:
    case spv::OpImageSparseFetch: case spv::OpImageSparseRead: case spv::OpImageSparseGather:
      return true;
    default:
      return false;
  }
}

// GLSL.std.450 instructions that work component by component on vectors.
bool isComponentwise(uint32_t glslInstruction) {
  switch (glslInstruction) {
    case GLSLstd450Length: case GLSLstd450Distance: case GLSLstd450Cross: case GLSLstd450Normalize:
    case GLSLstd450FaceForward: case GLSLstd450Reflect: case GLSLstd450Refract:
    case GLSLstd450Determinant: case GLSLstd450MatrixInverse:
    case GLSLstd450PackSnorm4x8: case GLSLstd450PackUnorm4x8: case GLSLstd450PackSnorm2x16:
    case GLSLstd450PackUnorm2x16: case GLSLstd450PackHalf2x16: case GLSLstd450PackDouble2x32:
    case GLSLstd450UnpackSnorm2x16: case GLSLstd450UnpackUnorm2x16: case GLSLstd450UnpackHalf2x16:
    case GLSLstd450UnpackSnorm4x8: case GLSLstd450UnpackUnorm4x8: case GLSLstd450UnpackDouble2x32:
    case GLSLstd450Modf: case GLSLstd450ModfStruct: case GLSLstd450FrexpStruct:
      return false;
    default:
      return true;
  }
}


std::string lower(std::string text) {
  for (auto& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "?" : out;
}

// Backward data flow over the real module: what a value (or one element of it, by access path) is
// computed from. Loads look at every store that may reach them, whatever the control flow (an
// over-approximation: a value counts as computed from every source it may come from).
class DataFlow {
 public:
  // `eyeParameters`: the injected eye-parameter variables / constants. `opaqueProducts`: products
  // whose result counts as computed from nothing (the fixed unprojections, when asking what else
  // a value depends on).
  DataFlow(const spirv::Module& m, bool hlsl, std::set<uint32_t> eyeParameters, std::set<uint32_t> opaqueProducts = {})
      : m_(m), hlsl_(hlsl), eyeParameters_(std::move(eyeParameters)), opaqueProducts_(std::move(opaqueProducts)) {
    for (const auto& fn : m.functions)
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions) {
          if (inst.opcode == spv::OpStore || inst.opcode == spv::OpCopyMemory) writes_.push_back(&inst);
          if (inst.opcode == spv::OpFunctionCall) callsTo_[inst.operand(0)].push_back(&inst);
          if (inst.opcode == spv::OpReturnValue) returnsOf_[fn.id()].push_back(inst.operand(0));
        }
    for (const auto& fn : m.functions)
      for (size_t i = 0; i < fn.parameters.size(); ++i) parameterOf_[fn.parameters[i].resultId] = {fn.id(), i};
    // Writes and pointer arguments by root, resolved once: loads ask for them again and again.
    for (const Instruction* write : writes_) {
      uint32_t root;
      Path path;
      if (resolvePointer(write->operand(0), &root, &path)) writesTo_[root].push_back({write, path});
    }
    for (const auto& [function, calls] : callsTo_)
      for (const Instruction* call : calls)
        for (size_t k = 1; k < call->operands.size(); ++k) {
          uint32_t root;
          Path path;
          if (resolvePointer(call->operands[k], &root, &path)) pointerArguments_[root].push_back({function, k - 1});
        }
  }

  Sources value(uint32_t id, Path path = {}) {
    // A dynamic index selects any element: the whole value answers for it.
    if (auto any = std::find(path.begin(), path.end(), kAnyIndex); any != path.end()) path.erase(any, path.end());
    auto key = std::make_pair(id, path);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    if (visiting_.count(key)) {
      Sources cut;
      cut.cycleCut = true;
      return cut;
    }
    if (++steps_ > kStepBudget) return otherSource();
    visiting_.insert(key);
    Sources result = compute(id, path);
    visiting_.erase(key);
    if (!result.cycleCut) cache_[key] = result;
    if (visiting_.empty()) result.cycleCut = false;
    return result;
  }

  // The root variable (or pointer parameter) of a pointer and the access path into it.
  bool resolvePointer(uint32_t pointer, uint32_t* root, Path* path) const {
    Path reversed;
    for (int depth = 0; depth < 64; ++depth) {
      const Instruction* def = m_.definition(pointer);
      if (!def) return false;
      switch (def->opcode) {
        case spv::OpVariable: case spv::OpFunctionParameter:
          *root = pointer;
          path->assign(reversed.rbegin(), reversed.rend());
          return true;
        case spv::OpAccessChain: case spv::OpInBoundsAccessChain:
          for (size_t k = def->operands.size(); k-- > 1;) {
            const Instruction* index = m_.definition(def->operands[k]);
            reversed.push_back(index && index->opcode == spv::OpConstant ? index->operand(0) : kAnyIndex);
          }
          pointer = def->operand(0);
          break;
        case spv::OpCopyObject:
          pointer = def->operand(0);
          break;
        default:
          return false;
      }
    }
    return false;
  }

  bool isFragCoord(uint32_t root, const Path& path) const {
    if (m_.decorationValue(root, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInFragCoord)) return true;
    const Instruction* var = m_.definition(root);
    if (!var || path.empty() || path[0] == kAnyIndex) return false;
    return m_.memberDecorationValue(m_.pointeeType(var->typeId), path[0], spv::DecorationBuiltIn) ==
           uint32_t(spv::BuiltInFragCoord);
  }

  std::string describe(uint32_t root, const Path& path) const {
    const Instruction* var = m_.definition(root);
    std::string name = m_.name(root);
    if (var && !path.empty() && path[0] != kAnyIndex) {
      uint32_t type = m_.pointeeType(var->typeId);
      const Instruction* typeDef = m_.definition(type);
      if (typeDef && typeDef->opcode == spv::OpTypeStruct) {
        std::string member = m_.memberName(type, path[0]);
        // HLSL cbuffers and globals are anonymous instances: their members are what the source names.
        if (name.empty() || name == "$Global") return member;
        return name + "." + member;
      }
    }
    return name.empty() ? "%" + std::to_string(root) : name;
  }

 private:
  static constexpr int kStepBudget = 200000;
  const spirv::Module& m_;
  bool hlsl_;
  std::set<uint32_t> eyeParameters_, opaqueProducts_;
  std::vector<const Instruction*> writes_;
  std::map<uint32_t, std::vector<const Instruction*>> callsTo_;
  std::map<uint32_t, std::vector<uint32_t>> returnsOf_;
  std::map<uint32_t, std::pair<uint32_t, size_t>> parameterOf_;  // parameter -> function, index
  std::map<uint32_t, std::vector<std::pair<const Instruction*, Path>>> writesTo_;  // root -> writes, paths
  std::map<uint32_t, std::vector<std::pair<uint32_t, size_t>>> pointerArguments_;  // root -> callee, parameter
  std::map<std::pair<uint32_t, Path>, Sources> cache_;
  std::set<std::pair<uint32_t, Path>> visiting_;
  int steps_ = 0;

  static Sources otherSource() {
    Sources s;
    s.other = true;
    return s;
  }

  bool isVector(uint32_t id) const {
    const Instruction* def = m_.definition(id);
    const Instruction* type = def ? m_.definition(def->typeId) : nullptr;
    return type && type->opcode == spv::OpTypeVector;
  }

  uint32_t componentCount(uint32_t id) const {
    const Instruction* def = m_.definition(id);
    const Instruction* type = def ? m_.definition(def->typeId) : nullptr;
    return type && type->opcode == spv::OpTypeVector ? type->operand(1) : 1;
  }

  Path rest(const Path& path) const { return Path(path.begin() + 1, path.end()); }

  std::string imageName(uint32_t image) const {
    for (int depth = 0; depth < 16; ++depth) {
      const Instruction* def = m_.definition(image);
      if (!def) break;
      if (def->opcode == spv::OpSampledImage || def->opcode == spv::OpImage || def->opcode == spv::OpCopyObject) {
        image = def->operand(0);
        continue;
      }
      if (def->opcode == spv::OpLoad) {
        uint32_t root;
        Path path;
        if (resolvePointer(def->operand(0), &root, &path)) return describe(root, path);
      }
      break;
    }
    return "?";
  }

  Sources compute(uint32_t id, const Path& path) {
    const Instruction* def = m_.definition(id);
    if (!def) return otherSource();
    Sources s;
    if (eyeParameters_.count(id)) {  // a specialization constant
      s.uniform = s.eyeParameter = true;
      return s;
    }
    if (opaqueProducts_.count(id)) {
      s.products.insert(id);
      return s;
    }
    switch (def->opcode) {
      case spv::OpConstant: case spv::OpConstantTrue: case spv::OpConstantFalse: case spv::OpConstantNull:
        s.constant = true;
        s.constantOtherThanOne = m_.floatConstant(def->resultId) != 1.0f;
        return s;
      case spv::OpConstantComposite:
        if (!path.empty() && path[0] < def->operands.size()) return value(def->operands[path[0]], rest(path));
        for (uint32_t element : def->operands) s |= value(element);
        return s;
      case spv::OpSpecConstant: case spv::OpSpecConstantTrue: case spv::OpSpecConstantFalse:
      case spv::OpSpecConstantComposite: case spv::OpSpecConstantOp:
        s.uniform = true;  // chosen by the application, like a uniform
        return s;
      case spv::OpUndef:
        return otherSource();
      case spv::OpCopyObject:
        return value(def->operand(0), path);
      case spv::OpLoad: {
        uint32_t root;
        Path pointerPath;
        if (!resolvePointer(def->operand(0), &root, &pointerPath)) return otherSource();
        pointerPath.insert(pointerPath.end(), path.begin(), path.end());
        return load(root, pointerPath);
      }
      case spv::OpCompositeExtract: {
        Path inner(def->operands.begin() + 1, def->operands.end());
        inner.insert(inner.end(), path.begin(), path.end());
        return value(def->operand(0), inner);
      }
      case spv::OpCompositeConstruct: {
        const Instruction* type = m_.definition(def->typeId);
        bool vector = type && type->opcode == spv::OpTypeVector;
        if (path.empty()) {
          for (uint32_t part : def->operands) s |= value(part);
          return s;
        }
        if (!vector) return path[0] < def->operands.size() ? value(def->operands[path[0]], rest(path)) : otherSource();
        uint32_t first = 0;  // vector constituents are flattened: find the one holding the component
        for (uint32_t part : def->operands) {
          uint32_t count = componentCount(part);
          if (path[0] < first + count) return value(part, isVector(part) ? Path{path[0] - first} : Path{});
          first += count;
        }
        return otherSource();
      }
      case spv::OpCompositeInsert: {
        Path at(def->operands.begin() + 2, def->operands.end());
        if (prefixOf(at, path)) return value(def->operand(0), Path(path.begin() + static_cast<long>(at.size()), path.end()));
        if (prefixOf(path, at)) {
          s |= value(def->operand(0));
          s |= value(def->operand(1), path);
          return s;
        }
        return value(def->operand(1), path);
      }
      case spv::OpVectorShuffle: {
        uint32_t firstCount = componentCount(def->operand(0));
        auto pick = [&](uint32_t component) {
          if (component == 0xFFFFFFFFu) return Sources{};  // undefined lane
          return component < firstCount ? value(def->operand(0), {component})
                                        : value(def->operand(1), {component - firstCount});
        };
        if (!path.empty()) return 2 + path[0] < def->operands.size() ? pick(def->operands[2 + path[0]]) : otherSource();
        for (size_t k = 2; k < def->operands.size(); ++k) s |= pick(def->operands[k]);
        return s;
      }
      case spv::OpPhi:
        for (size_t k = 0; k < def->operands.size(); k += 2) s |= value(def->operands[k], path);
        return s;
      case spv::OpSelect:
        for (uint32_t operand : def->operands) s |= value(operand, isVector(operand) ? path : Path{});
        return s;
      case spv::OpFAdd: case spv::OpFSub: case spv::OpFMul: case spv::OpFDiv: case spv::OpFMod:
      case spv::OpFRem: case spv::OpFNegate: case spv::OpIAdd: case spv::OpISub: case spv::OpIMul:
      case spv::OpSNegate: case spv::OpConvertFToS: case spv::OpConvertFToU: case spv::OpConvertSToF:
      case spv::OpConvertUToF: case spv::OpFConvert: case spv::OpBitcast: case spv::OpVectorTimesScalar:
      case spv::OpSDiv: case spv::OpUDiv: case spv::OpSMod: case spv::OpUMod: case spv::OpSRem:
      case spv::OpBitwiseAnd: case spv::OpBitwiseOr: case spv::OpBitwiseXor: case spv::OpNot:
      case spv::OpShiftLeftLogical: case spv::OpShiftRightLogical: case spv::OpShiftRightArithmetic:
      case spv::OpFOrdEqual: case spv::OpFOrdNotEqual: case spv::OpFOrdLessThan: case spv::OpFOrdGreaterThan:
      case spv::OpFOrdLessThanEqual: case spv::OpFOrdGreaterThanEqual: case spv::OpFUnordEqual:
      case spv::OpFUnordNotEqual: case spv::OpFUnordLessThan: case spv::OpFUnordGreaterThan:
      case spv::OpFUnordLessThanEqual: case spv::OpFUnordGreaterThanEqual: case spv::OpIEqual:
      case spv::OpINotEqual: case spv::OpSLessThan: case spv::OpSGreaterThan: case spv::OpSLessThanEqual:
      case spv::OpSGreaterThanEqual: case spv::OpULessThan: case spv::OpUGreaterThan:
      case spv::OpULessThanEqual: case spv::OpUGreaterThanEqual: case spv::OpLogicalAnd: case spv::OpLogicalOr:
      case spv::OpLogicalNot: case spv::OpLogicalEqual: case spv::OpLogicalNotEqual: case spv::OpIsNan:
      case spv::OpIsInf: case spv::OpDPdx: case spv::OpDPdy: case spv::OpFwidth: case spv::OpDPdxFine:
      case spv::OpDPdyFine: case spv::OpFwidthFine: case spv::OpDPdxCoarse: case spv::OpDPdyCoarse:
      case spv::OpFwidthCoarse:
        for (uint32_t operand : def->operands) s |= value(operand, isVector(operand) ? path : Path{});
        s.arithmetic = true;
        return s;
      case spv::OpExtInst: {
        bool componentwise = isComponentwise(def->operand(1));
        for (size_t k = 2; k < def->operands.size(); ++k)
          s |= value(def->operands[k], componentwise && isVector(def->operands[k]) ? path : Path{});
        s.arithmetic = true;
        return s;
      }
      case spv::OpMatrixTimesVector: case spv::OpVectorTimesMatrix:
        s.products.insert(id);
        [[fallthrough]];
      case spv::OpMatrixTimesMatrix: case spv::OpMatrixTimesScalar: case spv::OpDot: case spv::OpTranspose:
      case spv::OpOuterProduct: case spv::OpAny: case spv::OpAll: case spv::OpVectorExtractDynamic:
      case spv::OpVectorInsertDynamic:
        for (uint32_t operand : def->operands) s |= value(operand);
        s.arithmetic = true;
        return s;
      case spv::OpFunctionParameter: {  // a value parameter: whatever each call passes
        auto [function, index] = parameterOf_[id];
        for (const Instruction* call : callsTo_[function]) s |= value(call->operand(1 + index), path);
        if (callsTo_[function].empty()) s.other = true;
        return s;
      }
      case spv::OpFunctionCall:
        for (uint32_t returned : returnsOf_[def->operand(0)]) s |= value(returned, path);
        if (returnsOf_[def->operand(0)].empty()) s.other = true;
        return s;
      default:
        if (isImageRead(def->opcode)) {
          s.texel = true;
          s.textures.insert(imageName(def->operand(0)));
          return s;
        }
        return otherSource();  // depth comparisons, queries, atomics, derivatives, ...
    }
  }

  Sources load(uint32_t root, const Path& path) {
    const Instruction* def = m_.definition(root);
    if (!def) return otherSource();
    Sources s;
    if (def->opcode == spv::OpVariable) {
      switch (static_cast<spv::StorageClass>(def->operand(0))) {
        case spv::StorageClassInput:
          if (isFragCoord(root, path)) {
            // Only x, y are the pixel position; z (the fragment's depth) and w are the same per eye.
            size_t component = m_.hasDecoration(root, spv::DecorationBuiltIn) ? 0 : 1;
            if (path.size() > component && (path[component] == 2 || path[component] == 3)) return otherSource();
            s.fragCoord = true;
            s.inputs.insert(hlsl_ ? "SV_Position" : "gl_FragCoord");
          } else if (m_.hasDecoration(root, spv::DecorationBuiltIn)) {
            s.other = true;  // gl_FrontFacing, gl_SampleID, ...: not a screen position
          } else {
            s.varying = true;
            s.inputs.insert(describe(root, path));
          }
          return s;
        case spv::StorageClassUniform: case spv::StorageClassUniformConstant:
        case spv::StorageClassPushConstant: case spv::StorageClassStorageBuffer:
          s.uniform = true;
          s.eyeParameter = eyeParameters_.count(root) > 0;
          s.uniforms.insert(describe(root, path));
          return s;
        case spv::StorageClassFunction: case spv::StorageClassPrivate: case spv::StorageClassOutput:
          if (def->operands.size() > 1) s |= value(def->operand(1), path);  // initializer
          s |= stores(root, path);
          return s;
        default:
          return otherSource();
      }
    }
    if (def->opcode == spv::OpFunctionParameter) {  // a pointer parameter: the caller's memory
      s |= stores(root, path);
      auto [function, index] = parameterOf_[root];
      for (const Instruction* call : callsTo_[function]) {
        uint32_t argumentRoot;
        Path argumentPath;
        if (!resolvePointer(call->operand(1 + index), &argumentRoot, &argumentPath)) {
          s.other = true;
          continue;
        }
        argumentPath.insert(argumentPath.end(), path.begin(), path.end());
        s |= load(argumentRoot, argumentPath);
      }
      return s;
    }
    return otherSource();
  }

  // Every write that may reach a load of (root, path): stores to it, to a part of it or to a whole
  // that contains it; memory copies and writes by a callee through a pointer argument are opaque.
  Sources stores(uint32_t root, const Path& path) {
    Sources s;
    for (const auto& [write, targetPath] : writesTo_[root]) {
      if (write->opcode == spv::OpCopyMemory) {
        if (prefixOf(targetPath, path) || prefixOf(path, targetPath)) s.other = true;
        continue;
      }
      if (prefixOf(targetPath, path))
        s |= value(write->operand(1), Path(path.begin() + static_cast<long>(targetPath.size()), path.end()));
      else if (prefixOf(path, targetPath))
        s |= value(write->operand(1));
    }
    for (const auto& [function, index] : pointerArguments_[root]) {
      const spirv::Function* callee = m_.function(function);
      if (callee && index < callee->parameters.size() && !writesTo_[callee->parameters[index].resultId].empty())
        s.other = true;
    }
    return s;
  }
};

// One recognised unprojection, or the reason a matrix product is not one.
struct Product {
  spirv::Function* function = nullptr;
  uint32_t result = 0;
  bool vectorTimesMatrix = false;  // HLSL mul(M, v): v * M in SPIR-V, M's columns are HLSL rows
  uint32_t matrix = 0, vector = 0;
  Sources matrixSources, x, y, z, w, vectorSources;
  bool recognised = false;
  std::string reason;
};

class DeferredUnprojectionPass final : public Pass {
 public:
  const char* name() const override { return "deferred-unprojection"; }

  PassResult run(PassContext& ctx) override {
    auto& m = ctx.module;
    // A stereo depth buffer is read per pixel in fragment shaders; other stages transform forward.
    if (!ctx.options.deferredUnprojection || m.executionModel() != spv::ExecutionModelFragment)
      return PassResult::Unchanged;
    // Already converted (the eye parameters were there before this run): fixing q again would
    // subtract the parallax twice.
    if (!ctx.eyeDeclared && carriesEyeParameters(ctx)) {
      ctx.report["passes"][name()]["left_alone"] = "the shader already carries the eye parameters";
      return PassResult::Unchanged;
    }
    std::set<uint32_t> eyeParameters;
    if (ctx.eyeDeclared) {
      eyeParameters.insert(ctx.eye.variable);
      for (int i = 0; i < kEyeParamCount; ++i) {
        eyeParameters.insert(ctx.eye.looseVariables[i]);
        eyeParameters.insert(ctx.eye.specConstants[i]);
      }
      eyeParameters.erase(0);
    }
    bool hlsl = ctx.source.language == SourceLanguage::Hlsl;
    DataFlow flow(m, hlsl, eyeParameters);
    // Looked up, not created: an analysis that finds nothing must leave the module as it was.
    auto isFloat4 = [&](uint32_t type) {
      const Instruction* vector = m.definition(type);
      if (!vector || vector->opcode != spv::OpTypeVector || vector->operand(1) != 4) return false;
      const Instruction* component = m.definition(vector->operand(0));
      return component && component->opcode == spv::OpTypeFloat && component->operand(0) == 32;
    };

    std::vector<Product> products;
    for (auto& fn : m.functions)
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions) {
          if (inst.opcode != spv::OpMatrixTimesVector && inst.opcode != spv::OpVectorTimesMatrix) continue;
          if (!isFloat4(inst.typeId)) continue;  // a 4-component float point, or nothing to do here
          Product p;
          p.function = &fn;
          p.result = inst.resultId;
          p.vectorTimesMatrix = inst.opcode == spv::OpVectorTimesMatrix;
          p.matrix = p.vectorTimesMatrix ? inst.operand(1) : inst.operand(0);
          p.vector = p.vectorTimesMatrix ? inst.operand(0) : inst.operand(1);
          const Instruction* matrixType = m.definition(m.definition(p.matrix)->typeId);
          if (!matrixType || matrixType->operand(1) != 4) continue;  // only a mat4 maps NDC points
          products.push_back(std::move(p));
        }
    for (auto& p : products) classify(flow, p);
    // Products computed from the eye parameters were injected by an earlier pass (per-eye-view's
    // eye centre): stereo already, neither fixed nor reported.
    std::erase_if(products, [](const Product& p) { return p.matrixSources.eyeParameter || p.vectorSources.eyeParameter; });
    std::set<uint32_t> fixedResults;
    for (const auto& p : products)
      if (p.recognised) fixedResults.insert(p.result);

    auto& report = ctx.report["passes"][name()];
    nlohmann::json fixed = nlohmann::json::array(), leftAlone = nlohmann::json::array();
    for (const auto& p : products) {
      std::string matrixName = joined(p.matrixSources.uniforms);
      if (p.recognised) {
        fixed.push_back(describeFix(p, matrixName));
        continue;
      }
      // A product computed from a corrected position is already per-eye through it (e.g. the
      // light-space transform of the rebuilt world position for a shadow lookup).
      bool followsFix = std::any_of(p.vectorSources.products.begin(), p.vectorSources.products.end(),
                                    [&](uint32_t r) { return fixedResults.count(r) > 0; });
      nlohmann::json entry;
      entry["construct"] = "matrix * vector";
      entry["matrix"] = p.matrixSources.uniform ? matrixName : std::string("(not uniform)");
      entry["reason"] = followsFix ? "computed from a corrected unprojection: per-eye through it" : p.reason;
      leftAlone.push_back(entry);
    }
    DataFlow besidesFixes(m, hlsl, eyeParameters, fixedResults);
    reportFragCoordUses(ctx, besidesFixes, leftAlone);
    reportReflections(ctx, leftAlone);
    if (!fixed.empty()) report["fixed"] = fixed;
    if (!leftAlone.empty()) report["left_alone"] = leftAlone;
    if (fixed.empty()) return PassResult::Unchanged;

    if (!ensureEyeParams(ctx, kConvergence + 1)) return PassResult::Failed;
    for (const auto& p : products)
      if (p.recognised) rewrite(ctx, p);
    m.invalidateDefinitions();
    return PassResult::Changed;
  }

 private:
  static void classify(DataFlow& flow, Product& p) {
    p.matrixSources = flow.value(p.matrix);
    p.vectorSources = flow.value(p.vector);
    p.x = flow.value(p.vector, {0});
    p.y = flow.value(p.vector, {1});
    p.z = flow.value(p.vector, {2});
    p.w = flow.value(p.vector, {3});
    const Sources& mat = p.matrixSources;
    auto screenCoordinate = [](const Sources& s) {
      return (s.fragCoord || s.varying) && !s.texel && !s.other;
    };
    if (!mat.uniform || mat.fragCoord || mat.varying || mat.texel || mat.other) {
      p.reason = "the matrix is not uniform data";
    } else if (!(p.w.constant && !p.w.constantOtherThanOne && !p.w.arithmetic && !p.w.fragCoord && !p.w.varying &&
                 !p.w.texel && !p.w.uniform && !p.w.other)) {
      p.reason = p.w.constant && p.w.constantOtherThanOne && !p.w.arithmetic && !p.w.uniform && !p.w.other &&
                         !p.w.texel && !p.w.fragCoord && !p.w.varying
                     ? "w is a constant other than 1: a direction, not a point"
                     : "w is not the constant 1: not a point in NDC";
    } else if (!(p.z.texel && !p.z.fragCoord && !p.z.varying && !p.z.other)) {
      p.reason = "z is not a depth read from a texture";
    } else if (!screenCoordinate(p.x) || !screenCoordinate(p.y)) {
      p.reason = "x, y are not screen coordinates (gl_FragCoord or an interpolated UV)";
    } else {
      p.recognised = true;
    }
  }

  static nlohmann::json describeFix(const Product& p, const std::string& matrixName) {
    nlohmann::json entry;
    entry["matrix"] = matrixName;
    // The fix is the same for both; the form only tells a person which space the result is in,
    // judged from the matrix's name.
    std::string n = lower(matrixName);
    if (n.find("view") != std::string::npos || matrixName.find("VP") != std::string::npos)
      entry["form"] = "world position from an inverse view-projection";
    else if (n.find("proj") != std::string::npos)
      entry["form"] = "view-space position from an inverse projection";
    else
      entry["form"] = "position from an inverse matrix (space unknown from its name)";
    entry["depth"] = joined(p.z.textures);
    entry["depth_range"] = p.z.arithmetic ? "remapped in the shader (e.g. depth * 2 - 1)" : "as sampled ([0, 1])";
    std::set<std::string> ndc = p.x.inputs;
    ndc.insert(p.y.inputs.begin(), p.y.inputs.end());
    entry["ndc"] = joined(ndc);
    entry["fix"] = "q - " + matrixName + "[col 0] * eyeSign*separation*(1 - convergence*q.w), before the divide";
    return entry;
  }

  // q' = eyeSign != 0 ? q - InvM[col 0] * (eyeSign*separation)*(1 - convergence*q.w) : q.
  // The select keeps a mono draw the original bit for bit (no -0 turned into +0, no 0*inf NaN).
  static void rewrite(PassContext& ctx, const Product& p) {
    auto& m = ctx.module;
    uint32_t f = m.typeFloat(32), v4 = m.typeVector(f, 4), bool4 = m.typeVector(m.typeBool(), 4);
    std::vector<Instruction> code;
    auto emit = [&](spv::Op op, uint32_t type, std::vector<uint32_t> operands) {
      uint32_t id = m.takeId();
      code.emplace_back(op, type, id, std::move(operands));
      return id;
    };
    uint32_t column0;
    if (!p.vectorTimesMatrix) {
      column0 = emit(spv::OpCompositeExtract, v4, {p.matrix, 0});
    } else {  // v * M: the mathematical matrix is M transposed, its column 0 is element 0 of each column of M
      std::vector<uint32_t> elements;
      for (uint32_t c = 0; c < 4; ++c) elements.push_back(emit(spv::OpCompositeExtract, f, {p.matrix, c, 0}));
      column0 = emit(spv::OpCompositeConstruct, v4, elements);
    }
    uint32_t eyeSign = emitLoadEyeParam(ctx, code, kEyeSign);
    uint32_t separation = emitLoadEyeParam(ctx, code, kSeparation);
    uint32_t convergence = emitLoadEyeParam(ctx, code, kConvergence);
    uint32_t inverseDepth = emit(spv::OpCompositeExtract, f, {p.result, 3});
    uint32_t scaled = emit(spv::OpFMul, f, {convergence, inverseDepth});
    uint32_t parallax = emit(spv::OpFSub, f, {m.constantFloat(1.0f), scaled});
    uint32_t scale = emitEyeScale(ctx, code, eyeSign, separation);
    uint32_t offset = emit(spv::OpFMul, f, {scale, parallax});
    uint32_t correction = emit(spv::OpVectorTimesScalar, v4, {column0, offset});
    uint32_t corrected = emit(spv::OpFSub, v4, {p.result, correction});
    m.constantFloat(0.0f);  // before the guard's own id, the order these ids have always had
    uint32_t stereo = emitStereoGuard(ctx, code, eyeSign);
    // A vector condition: OpSelect takes a scalar one only from SPIR-V 1.4 on.
    uint32_t stereo4 = emit(spv::OpCompositeConstruct, bool4, {stereo, stereo, stereo, stereo});
    uint32_t chosen = emit(spv::OpSelect, v4, {stereo4, corrected, p.result});

    // Every use of q now reads q' (the fix code itself, inserted below, still reads q).
    for (auto& block : p.function->blocks)
      for (auto& inst : block.instructions)
        for (size_t k = 0; k < inst.operands.size(); ++k)
          if (inst.operands[k] == p.result && spirv::isValueOperand(inst, k)) inst.operands[k] = chosen;
    for (auto& block : p.function->blocks)
      for (size_t i = 0; i < block.instructions.size(); ++i)
        if (block.instructions[i].resultId == p.result) {
          block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
          m.invalidateDefinitions();
          return;
        }
  }

  // gl_FragCoord values that reach an output or a branch other than through a fixed unprojection
  // or a texture lookup (reading this eye's G-buffer at this eye's pixel is per-eye already):
  // screen-space effects computed from the pixel position, left as they are. `flow` treats the
  // fixed unprojections as opaque and never looks through an image coordinate.
  static void reportFragCoordUses(PassContext& ctx, DataFlow& flow, nlohmann::json& leftAlone) {
    auto& m = ctx.module;
    std::set<std::string> reaches;
    for (const auto& fn : m.functions)
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions) {
          if (inst.opcode == spv::OpStore) {
            uint32_t root;
            Path path;
            if (!flow.resolvePointer(inst.operand(0), &root, &path) ||
                m.storageClassOf(root) != spv::StorageClassOutput)
              continue;
            if (flow.value(inst.operand(1)).fragCoord) reaches.insert(flow.describe(root, path));
          } else if (inst.opcode == spv::OpBranchConditional || inst.opcode == spv::OpSwitch) {
            if (flow.value(inst.operand(0)).fragCoord) reaches.insert("a branch (e.g. a discard)");
          }
        }
    for (const auto& target : reaches) {
      nlohmann::json entry;
      entry["construct"] = ctx.source.language == SourceLanguage::Hlsl ? "SV_Position" : "gl_FragCoord";
      entry["reaches"] = target;
      entry["reason"] = "screen-space computation from this eye's pixel position, left as it is: check by eye";
      leftAlone.push_back(entry);
    }
  }

  static void reportReflections(PassContext& ctx, nlohmann::json& leftAlone) {
    auto& m = ctx.module;
    uint32_t glsl = 0;
    for (const auto& inst : m.extInstImports)
      if (inst.stringOperand(0) == "GLSL.std.450") glsl = inst.resultId;
    if (!glsl) return;
    int reflections = 0, refractions = 0;
    for (const auto& fn : m.functions)
      for (const auto& block : fn.blocks)
        for (const auto& inst : block.instructions)
          if (inst.opcode == spv::OpExtInst && inst.operand(0) == glsl) {
            reflections += inst.operand(1) == GLSLstd450Reflect;
            refractions += inst.operand(1) == GLSLstd450Refract;
          }
    auto add = [&](int count, const char* what) {
      if (!count) return;
      nlohmann::json entry;
      entry["construct"] = what;
      entry["count"] = count;
      entry["reason"] = "built from the shader's view vector: with a mono camera position both eyes see "
                        "the mono reflection; check by eye";
      leftAlone.push_back(entry);
    };
    add(reflections, "reflect()");
    add(refractions, "refract()");
  }
};

}  // namespace

std::unique_ptr<Pass> createDeferredUnprojectionPass() { return std::make_unique<DeferredUnprojectionPass>(); }

}  // namespace stereoshift
